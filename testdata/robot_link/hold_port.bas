// Holds the robot's port while it waits for a line of input, then lets it go (rCommPort 0)
// and waits again: link_tests.py checks that a second run finds the port busy, then free.
// args: --port /nonexistent/robot
rCommPort 1  // expect-runtime-error: cannot open robot port /nonexistent/robot: no such device
rForward 10
print "holding"
input a
rCommPort 0
print "released"
input b
