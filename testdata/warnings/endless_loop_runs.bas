// args: --max-steps 30
// The warning is true: this loop goes round until the step limit stops it.
rLocate 400, 300
turns = 0
while turns < 4 // expect-warning: this loop never ends once it repeats: nothing in it changes 'turns' // expect-runtime-error: stopped after 30 steps (the --max-steps limit)
  rTurn 90
wend
