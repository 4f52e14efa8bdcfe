// rb check --portable: a built-in no public RobotBASIC source names is rb's own, and each use
// of one is a warning, with a note saying what RobotBASIC is known to have instead where there
// is such a thing (testdata/diagnostics/portable.t shows the notes). Names a source shows stay
// quiet: rLocate, rForward, random, ascii, round, sign, pi, Red, True.
// check-args: --portable
rLocate 400, 300
rForward 10
d = rtod(0)  // expect-warning: 'rtod' is rb's own: no public RobotBASIC source names it
print d
// expect: 0
s = trimL("  robot")  // expect-warning: 'trimL' is rb's own: no public RobotBASIC source names it
print s
// expect: robot
if contains(s, "bot") then print "found"  // expect-warning: 'contains' is rb's own: no public RobotBASIC source names it
// expect: found
print kc_Enter  // expect-warning: 'kc_Enter' is rb's own: no public RobotBASIC source names it
// expect: 13
rectangleWH 10, 10, 20, 20, Red  // expect-warning: 'rectangleWH' is rb's own: no public RobotBASIC source names it
flip on  // expect-warning: 'flip' is rb's own: no public RobotBASIC source names it // expect-warning: 'On' is rb's own: no public RobotBASIC source names it
print random(1) + ascii("A") + round(2.4) + sign(-3) + True
// expect: 67
print rGPSY() < 300 and pi() > 3
// expect: 1
