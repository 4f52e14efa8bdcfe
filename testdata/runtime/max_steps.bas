// args: --max-steps 1000
// The step limit stops a program that never ends.
while true // expect-runtime-error: stopped after 1000 steps (the --max-steps limit)
  x = 1
wend
