// The text toNumber could not read is quoted whole, its control characters escaped: the NUL
// does not end the message.
print toNumber("12" + char(0) + "x" + char(27)) // expect-runtime-error: toNumber(): "12\x00x\x1b" is not a number
