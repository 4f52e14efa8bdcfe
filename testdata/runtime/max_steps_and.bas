// args: --max-steps 1000
// A condition whose `and` falls through on its left side still counts its statement: the
// step limit stops this loop (it once ran forever).
x = 0
while 1 // expect-runtime-error: stopped after 1000 steps (the --max-steps limit)
  if x = 1 and x = 2
    print "never"
  endif
wend
