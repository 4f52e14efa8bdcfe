// A misspelt closer is one mistake, reported once where it is: it closes the block it would
// close, its message says which, and that block is not reported again as unclosed at the end
// of the file (which would come first, though it is only the consequence).
for i = 1 to 3
  print i
nxt // expect-error: unknown command 'nxt'; did you mean 'next'? (the for at line 4 has no next)
x = 0
while x < 3
  x = x + 1
wnd // expect-error: unknown command 'wnd'; did you mean 'wend'? (the while at line 8 has no wend)
repeat
  x = x - 1
untl x = 0 // expect-error: unknown command 'untl'; did you mean 'until'? (the repeat at line 11 has no until)
if x = 0 then
  print x
endf // expect-error: unknown command 'endf'; did you mean 'endif'? (the if at line 14 has no endif)
// The inner loop's closer misspelt: the outer loop's next still closes the outer loop.
for i = 1 to 3
  for j = 1 to 3
    print i * j
  Nxt // expect-error: unknown command 'Nxt'; did you mean 'next'? (the for at line 19 has no next)
next
// A closer of another block than the innermost one, or of none, closes nothing.
for k = 1 to 2
  wnd // expect-error: unknown command 'wnd'; did you mean 'wend'?
next
nxt // expect-error: unknown command 'nxt'; did you mean 'next'?
// Nor does one in a single-line if (where no closer can stand); one after a label does.
for m = 1 to 2
  if m = 1 then nxt // expect-error: unknown command 'nxt'; did you mean 'next'?
next
for m = 1 to 2
again: nxt // expect-error: unknown command 'nxt'; did you mean 'next'? (the for at line 32 has no next)
sub Count()
  for n = 1 to 2
    print n
  nxt // expect-error: unknown command 'nxt'; did you mean 'next'? (the for at line 35 has no next)
endsub
