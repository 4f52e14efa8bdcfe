// args: --max-steps 40
// Every statement that runs counts, the body of a true `if` too: 1 + 6 per pass (while, if,
// three assignments, print) leaves 3 steps for the 7th pass, which ends in its body.
n = 0
while 1 // expect-runtime-error: stopped after 40 steps (the --max-steps limit)
  if 1
    n = n + 1
    n = n + 1
    n = n + 1
  endif
  print n // expect: 3
  // expect: 6
  // expect: 9
  // expect: 12
  // expect: 15
  // expect: 18
wend
