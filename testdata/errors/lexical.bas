// Lexical errors are reported with their position; the rest of the file is still checked.
x = 1 @ 2 // expect-error: unexpected character '@'
print "open // expect-error: unterminated string (a string must close on the same line)
y = 0x1FFFFFFFFFFFFFFFFF // expect-error: hexadecimal number too large
