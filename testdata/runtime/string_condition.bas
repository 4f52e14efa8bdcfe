s = "yes"
while s // expect-warning: this loop never ends once it repeats: nothing in it changes 's' // expect-runtime-error: a condition must be a number, not a string
wend
