# rb check --portable: rb's own built-ins and statement forms, each with the note that says what
# RobotBASIC is known to have instead where there is one; without the option, nothing.
$ rb check --color=never inputs/portable.bas
[exit 0]

$ rb check --color=never --portable inputs/portable.bas
inputs/portable.bas:2:5: warning: 'kc_Enter' is rb's own: no public RobotBASIC source names it [rb-not-portable]
    2 | x = kc_Enter + rtod(1)
      |     ^~~~~~~~
note: what RobotBASIC is known to have instead: 13 (getKey gives character codes)
inputs/portable.bas:3:1: warning: 'line' is rb's own: no public RobotBASIC source names it [rb-not-portable]
    3 | line 1, 2, 3, 4
      | ^~~~
note: what RobotBASIC is known to have instead: gotoXY x1, y1 then lineTo x2, y2
inputs/portable.bas:4:23: warning: 'else' in a single-line if is rb's own: no public RobotBASIC source shows it [rb-not-portable]
    4 | if x > 1 then print x else print 0
      |                       ^~~~
note: what RobotBASIC is known to have instead: a block if ... else ... endif (seed, Figure 1.13)
3 warnings
[exit 0]
