print sqrt(-1) // expect-runtime-error: sqrt(): the square root of a negative number is not defined
