print toNumber("12x", -1) // expect: -1
print toNumber("12x") // expect-runtime-error: toNumber(): "12x" is not a number
