// A robot fault stops the program at the statement that met it, naming the port. Here the
// port is missing; link_tests.py runs the same program against the robot emulator rehearsing
// each fault on the third command (line 9).
// args: --port /nonexistent/robot
print "start"  // expect: start
rCommPort 5    // expect-runtime-error: cannot open robot port /nonexistent/robot: no such device
rForward 10
rTurn 90
rForward 10
print "not reached"
