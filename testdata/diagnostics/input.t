# Files from Windows and files that are not programs: a byte-order mark is skipped,
# Windows-1252 text is read and printed as UTF-8, binary input is reported once.
$ rb run inputs/bom.bas
café
[exit 0]

$ rb check --color=never inputs/cp1252.bas
inputs/cp1252.bas:3:1: error: unknown command 'prnt'; did you mean 'print'? [rb-unknown-command]
    3 | prnt "été"
      | ^~~~
      | print
1 error
[exit 65]

$ rb check --color=never inputs/binary.dat
inputs/binary.dat: error: this is a binary file, not a program (it holds a NUL byte at byte 8) [rb-binary-input]
1 error
[exit 65]

$ rb run --color=never inputs/binary.dat
inputs/binary.dat: error: this is a binary file, not a program (it holds a NUL byte at byte 8) [rb-binary-input]
1 error
[exit 65]

