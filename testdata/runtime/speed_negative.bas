rSpeed -1 // expect-runtime-error: argument 1 (delay) of rSpeed must not be negative
