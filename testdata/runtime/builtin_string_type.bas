print left(5, 1) // expect-runtime-error: argument 1 (s) of left() must be a string, not a number
