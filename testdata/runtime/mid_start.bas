print mid("abc", 0, 1) // expect-runtime-error: argument 2 (start) of mid() must be 1 or more (1 is the first character)
