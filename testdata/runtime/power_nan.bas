print (-8) ^ 0.5 // expect-runtime-error: the result is not a number
