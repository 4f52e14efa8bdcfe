print rtod(1e307) // expect-runtime-error: the result is too large
