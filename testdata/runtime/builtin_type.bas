print sqrt("4") // expect-runtime-error: argument 1 (x) of sqrt() must be a number, not a string
