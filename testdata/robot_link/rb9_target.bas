// rb check --target rb9: what the RB-9 cannot do. On the simulator the program runs as usual.
// check-args: --target rb9
rLocate 100,300,90
rForward 300  // expect-warning: rForward 300: the RB-9 moves at most about 250 per command (the seed recommends staying below 200); use several shorter moves
rForward 250
rForward -260  // expect-warning: rForward -260: the RB-9 moves at most about 250 per command (the seed recommends staying below 200); use several shorter moves
d = 100
rForward d
rTurn 360
c = rLook()  // expect-warning: rLook(): the RB-9 has no camera, so the real robot cannot report colours
if rGPSX() > 0 then print rGPSY()  // expect-warning: rGPSX(): the RB-9 has no GPS; track the position from its moves and rCompass() // expect-warning: rGPSY(): the RB-9 has no GPS; track the position from its moves and rCompass()
print rChargeLevel() > 0  // expect-warning: rChargeLevel(): the robot protocol has no battery command, so this stops the program on a real robot
print rRange() + rCompass() + rFeel() + rBumper() + rSense() + rBeacon(RED) >= 0
// expect: 300
// expect: 1
// expect: 1
