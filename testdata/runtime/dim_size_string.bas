dim a["3"] // expect-runtime-error: array size must be a number, not a string
