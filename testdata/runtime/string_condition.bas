s = "yes"
while s // expect-runtime-error: a condition must be a number, not a string
wend
