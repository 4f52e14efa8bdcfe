# rb check's text output: gutter, ranges, rule codes, fix-its, notes, the limit and the summary;
# the warnings about a program's flow.
$ rb check --color=never inputs/errors.bas
inputs/errors.bas:2:11: error: expected ')', found end of line [rb-syntax]
    2 | x = (1 + 2
      |           ^
inputs/errors.bas:4:1: error: unknown command 'rForwrd'; did you mean 'rForward'? [rb-unknown-command]
    4 | rForwrd 120
      | ^~~~~~~
      | rForward
inputs/errors.bas:5:12: error: 'abs()' takes 1 argument, got 3 [rb-argument-count]
    5 | y = abs(1, 2, 3)
      |            ^~~~
note: usage: abs(x)
inputs/errors.bas:6:5: error: 'left()' takes 2 arguments, got 1 [rb-argument-count]
    6 | z = left("a")
      |     ^~~~
note: usage: left(s, n)
inputs/errors.bas:7:24: error: 'rLocate' takes 2 to 5 arguments, got 7 [rb-argument-count]
    7 | rLocate 1, 2, 3, 4, 5, 6, 7
      |                        ^~~~
note: usage: rLocate x, y [, heading [, radius [, colour]]]
inputs/errors.bas:8:6: error: undefined label 'nowher'; did you mean 'nowhere'? [rb-undefined-label]
    8 | goto nowher
      |      ^~~~~~
      |      nowhere
inputs/errors.bas:11:7: warning: variable 'total' is read but never assigned; did you mean 'Total'? (names are case-sensitive) [rb-unassigned-variable]
   11 | print total
      |       ^~~~~
      |       Total
inputs/errors.bas:12:16: error: sub 'Two' takes 2 arguments, got 3 [rb-argument-count]
   12 | call Two(1, 2, 3)
      |                ^
inputs/errors.bas:16:5: note: 'Two' is defined here
   16 | sub Two(a, b)
      |     ^~~
inputs/errors.bas:13:1: warning: if without endif before the next sub; the block runs to that point [rb-unclosed-if]
   13 | if y > 1
      | ^~
7 errors, 2 warnings
[exit 65]

$ rb check --color=never inputs/side_by_side.bas
inputs/side_by_side.bas:3:25: error: missing '+' between 'n' and " moves" [rb-missing-operator]
    3 | print "reached in " + n " moves"
      |                         ^~~~~~~~
      |                         +
inputs/side_by_side.bas:4:13: error: missing '+' between "x = " and 'n' [rb-missing-operator]
    4 | msg = "x = "n
      |             ^
      |              +
inputs/side_by_side.bas:5:11: error: missing '*' between '2' and 'n' [rb-missing-operator]
    5 | total = 2 n
      |           ^
      |           *
inputs/side_by_side.bas:6:17: error: missing '*' between '(n + 1)' and 'n' [rb-missing-operator]
    6 | total = (n + 1) n
      |                 ^
      |                 *
inputs/side_by_side.bas:7:9: error: missing ',' between 'n' and '2' [rb-missing-operator]
    7 | print n 2
      |         ^
      |        ,
5 errors
[exit 65]

$ rb check --color=never inputs/flow.bas
inputs/flow.bas:2:1: warning: the robot is not placed yet when 'rForward' runs: rLocate x, y places it [rb-robot-not-placed]
    2 | rForward 100
      | ^~~~~~~~
inputs/flow.bas:5:7: warning: this loop never ends once it repeats: nothing in it changes 'sides' [rb-endless-loop]
    5 | while sides < 4
      |       ^~~~~
inputs/flow.bas:9:7: warning: label 'Inner' is inside sub 'Draw': a gosub from outside the sub runs its code without the sub's variables; call the sub, or move the label out of it [rb-jump-into-sub]
    9 | gosub Inner
      |       ^~~~~
inputs/flow.bas:13:1: note: 'Inner' is defined here
   13 | Inner:
      | ^~~~~
inputs/flow.bas:12:5: warning: sub 'Draw' is never called [rb-unused-sub]
   12 | sub Draw(size)
      |     ^~~~
inputs/flow.bas:17:1: warning: label 'Spare' is never used: no goto or gosub jumps to it, so the code after it never runs [rb-unused-label]
   17 | Spare:
      | ^~~~~
5 warnings
[exit 0]

$ rb check --color=never inputs/include.bas
In file included from inputs/include.bas:2:
inputs/lib_bad.bas:2:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    2 | prnt "from the library"
      | ^~~~
      | print
1 error
[exit 65]

$ rb check --color=never inputs/many.bas
inputs/many.bas:2:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    2 | prnt 0
      | ^~~~
      | print
inputs/many.bas:3:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    3 | prnt 1
      | ^~~~
      | print
inputs/many.bas:4:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    4 | prnt 2
      | ^~~~
      | print
inputs/many.bas:5:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    5 | prnt 3
      | ^~~~
      | print
inputs/many.bas:6:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    6 | prnt 4
      | ^~~~
      | print
inputs/many.bas:7:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    7 | prnt 5
      | ^~~~
      | print
inputs/many.bas:8:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    8 | prnt 6
      | ^~~~
      | print
inputs/many.bas:9:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    9 | prnt 7
      | ^~~~
      | print
inputs/many.bas:10:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   10 | prnt 8
      | ^~~~
      | print
inputs/many.bas:11:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   11 | prnt 9
      | ^~~~
      | print
inputs/many.bas:12:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   12 | prnt 10
      | ^~~~
      | print
inputs/many.bas:13:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   13 | prnt 11
      | ^~~~
      | print
inputs/many.bas:14:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   14 | prnt 12
      | ^~~~
      | print
inputs/many.bas:15:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   15 | prnt 13
      | ^~~~
      | print
inputs/many.bas:16:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   16 | prnt 14
      | ^~~~
      | print
inputs/many.bas:17:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   17 | prnt 15
      | ^~~~
      | print
inputs/many.bas:18:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   18 | prnt 16
      | ^~~~
      | print
inputs/many.bas:19:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   19 | prnt 17
      | ^~~~
      | print
inputs/many.bas:20:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   20 | prnt 18
      | ^~~~
      | print
inputs/many.bas:21:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
   21 | prnt 19
      | ^~~~
      | print
stopped after 20 errors (--max-errors; --max-errors 0 shows them all)
25 errors
[exit 65]

$ rb check --color=never --max-errors 2 inputs/include.bas inputs/many.bas
In file included from inputs/include.bas:2:
inputs/lib_bad.bas:2:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    2 | prnt "from the library"
      | ^~~~
      | print
inputs/many.bas:2:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    2 | prnt 0
      | ^~~~
      | print
stopped after 2 errors (--max-errors; --max-errors 0 shows them all)
26 errors
[exit 65]

$ rb check --color=always inputs/include.bas
In file included from inputs/include.bas:2:
[1minputs/lib_bad.bas:2:1:[m [1;31merror:[m unknown command 'prnt'; did you mean 'print'? [[1;31mrb-unknown-command[m]
    2 | prnt "from the library"
      | [1;32m^~~~[m
      | [1;32mprint[m
1 error
[exit 65]

$ rb check --format github inputs/errors.bas
::error file=inputs/errors.bas,line=2,col=11,title=rb-syntax::expected ')', found end of line
::error file=inputs/errors.bas,line=4,col=1,endColumn=8,title=rb-unknown-command::unknown command 'rForwrd'; did you mean 'rForward'?
::error file=inputs/errors.bas,line=5,col=12,endColumn=16,title=rb-argument-count::'abs()' takes 1 argument, got 3%0Ausage: abs(x)
::error file=inputs/errors.bas,line=6,col=5,endColumn=9,title=rb-argument-count::'left()' takes 2 arguments, got 1%0Ausage: left(s, n)
::error file=inputs/errors.bas,line=7,col=24,endColumn=28,title=rb-argument-count::'rLocate' takes 2 to 5 arguments, got 7%0Ausage: rLocate x, y [, heading [, radius [, colour]]]
::error file=inputs/errors.bas,line=8,col=6,endColumn=12,title=rb-undefined-label::undefined label 'nowher'; did you mean 'nowhere'?
::warning file=inputs/errors.bas,line=11,col=7,endColumn=12,title=rb-unassigned-variable::variable 'total' is read but never assigned; did you mean 'Total'? (names are case-sensitive)
::error file=inputs/errors.bas,line=12,col=16,title=rb-argument-count::sub 'Two' takes 2 arguments, got 3%0Aline 16: 'Two' is defined here
::warning file=inputs/errors.bas,line=13,col=1,endColumn=3,title=rb-unclosed-if::if without endif before the next sub; the block runs to that point
[exit 65]

$ rb check --color=never inputs/missing.bas
inputs/missing.bas: error: cannot read 'inputs/missing.bas': no such file [rb-unreadable-file]
1 error
[exit 66]

