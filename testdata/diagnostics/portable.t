# rb check --portable: rb's own built-ins and statement forms, each with the note that says what
# RobotBASIC is known to have instead where there is one; without the option, nothing.
$ rb check --color=never inputs/portable.bas
[exit 0]

$ rb check --color=never --portable inputs/portable.bas
inputs/portable.bas:2:5: warning: 'rtod' is rb's own: no public RobotBASIC source names it [rb-not-portable]
    2 | x = rtod(1)
      |     ^~~~
note: what RobotBASIC is known to have instead: x * 180 / pi()
inputs/portable.bas:3:5: warning: 'trimL' is rb's own: no public RobotBASIC source names it [rb-not-portable]
    3 | s = trimL(" a")
      |     ^~~~~
inputs/portable.bas:4:25: warning: 'else' in a single-line if is rb's own: no public RobotBASIC source shows it [rb-not-portable]
    4 | if s = "a" then print x else print s
      |                         ^~~~
note: what RobotBASIC is known to have instead: a block if ... else ... endif (seed, Figure 1.13)
inputs/portable.bas:5:16: warning: 'step' in a for loop is rb's own: no public RobotBASIC source shows it [rb-not-portable]
    5 | for i = 1 to 3 step 2
      |                ^~~~
4 warnings
[exit 0]
