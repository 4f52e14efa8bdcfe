// args: --max-steps 1000
// `until` with an `and` counts every pass: the step limit stops this loop (it once ran forever).
repeat
until 1 and 0 // expect-runtime-error: stopped after 1000 steps (the --max-steps limit)
