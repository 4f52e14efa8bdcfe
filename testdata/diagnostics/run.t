# rb run's diagnostics: load warnings (or --quiet), runtime errors with their call chain, the
# did-you-mean at run time, and what the robot crashed into.
$ rb run --color=never inputs/warnings.bas
in the if
inputs/warnings.bas:2:1: warning: if without endif before the end of the file; the block runs to that point [rb-unclosed-if]
[exit 0]

$ rb run --color=never --quiet inputs/warnings.bas
in the if
[exit 0]

$ rb run --color=never inputs/runtime.bas
inputs/runtime.bas:9:14: error: variable 'real' is used before it is given a value; did you mean 'Real'? (names are case-sensitive) [rb-runtime-error]
    9 |   print n / (real - 2)
      |              ^~~~
inputs/runtime.bas:6:3: note: in sub 'Inner' called from line 6
    6 |   call Inner(1)
      |   ^~~~
inputs/runtime.bas:3:1: note: in the gosub called from line 3
    3 | gosub Outer
      | ^~~~~
[exit 70]

$ rb run --color=never inputs/include.bas
In file included from inputs/include.bas:2:
inputs/lib_bad.bas:2:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    2 | prnt "from the library"
      | ^~~~
      | print
1 error
[exit 65]

$ rb run --color=never inputs/crash_trail.bas
inputs/crash_trail.bas:5:1: error: robot crashed into an obstacle: its own pen trail (colour Black); add 'rInvisible Black' before 'rPen down' so the robot does not see its trail [rb-robot-crash]
    5 | rForward -1
      | ^~~~~~~~
[exit 70]

$ rb run --color=never inputs/crash_wall.bas
inputs/crash_wall.bas:5:1: error: robot crashed into an obstacle: colour Black at (400, 202) [rb-robot-crash]
    5 | rForward 200
      | ^~~~~~~~
[exit 70]

$ rb run --color=never inputs/include_runtime.bas
In file included from inputs/include_runtime.bas:2:
inputs/lib_runtime.bas:3:14: error: variable 'd' is used before it is given a value [rb-runtime-error]
    3 |   return n / d
      |              ^
inputs/include_runtime.bas:3:7: note: in sub 'Half' called from line 3
    3 | print Half(4)
      |       ^~~~
[exit 70]

