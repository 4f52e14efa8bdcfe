// check-args: --target rb9
// Checked for a real robot (--target rb9), which needs no rLocate: no warning. The simulator
// still stops.
rForward 10 // expect-runtime-error: the robot has not been placed: use rLocate x, y first
