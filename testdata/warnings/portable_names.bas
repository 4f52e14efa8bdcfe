// rb check --portable: a built-in no public RobotBASIC source names is rb's own, and each use
// of one is a warning, with a note saying what RobotBASIC is known to have instead where there
// is such a thing (testdata/diagnostics/portable.t shows the notes). Names a source shows stay
// quiet (rLocate, rForward, random, ascii, round, sign, pi, Red, True), and so do the names the
// research notes recall from RobotBASIC's manual (sqrt, rtod, trimL, contains, Yellow, rectangleWH, flip, On).
// check-args: --portable
rLocate 400, 300
rForward 10
d = sqrt(16)
print d
// expect: 4
print rtod(0)
// expect: 0
s = trimL("  robot")
if contains(s, "bot") then print "found"
// expect: found
print kc_Enter  // expect-warning: 'kc_Enter' is rb's own: no public RobotBASIC source names it
// expect: 13
line 10, 10, 20, 20  // expect-warning: 'line' is rb's own: no public RobotBASIC source names it
eCircle 30, 30, 40, 40, Yellow  // expect-warning: 'eCircle' is rb's own: no public RobotBASIC source names it
saveScr  // expect-warning: 'saveScr' is rb's own: no public RobotBASIC source names it
rectangleWH 10, 10, 20, 20, Red
flip on
print random(1) + ascii("A") + round(2.4) + sign(-3) + True
// expect: 67
print rGPSY() < 300 and pi() > 3
// expect: 1
