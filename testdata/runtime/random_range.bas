print random(0) // expect-runtime-error: random(n) needs n >= 1, got 0
