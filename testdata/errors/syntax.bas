// Syntax errors: every bad line is reported, each once.
#define X // expect-error: unknown directive: only #include is supported
#include missing // expect-error: expected a file name in quotes after #include, found 'missing'
if x then for i = 1 to 2 // expect-error: 'for' cannot be part of a single-line if (put it on its own line)
rForward 10 20 // expect-error: unexpected '20' after the end of the statement
input 5 // expect-error: input needs a variable to store what is typed
if x print 1 // expect-error: expected 'then' or the end of the line after the if condition, found 'print'
x = (1 + 2 // expect-error: expected ')', found end of line
x = 1 + // expect-error: expected an expression, found end of line
x = then // expect-error: expected an expression, found the keyword 'then'
for = 1 // expect-error: expected the loop variable after for, found '='
for i = 1 10 // expect-error: expected 'to', found a number
goto // expect-error: expected a label name, found end of line
dim // expect-error: expected an array name after dim, found end of line
data d 1, 2 // expect-error: expected ';' after the array name, found a number
sub (a) // expect-error: expected a sub name, found '('
a[1 2] = 3 // expect-error: expected ']' to close the index, found a number
x = foo(1 // expect-error: expected ')' to close the argument list, found end of line
for step = 1 to 3 // expect-error: expected the loop variable after for, found 'step'
  print 1
next
while (1 // expect-error: expected ')', found end of line
wend
repeat
until // expect-error: expected an expression, found end of line
