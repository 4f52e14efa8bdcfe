b[1] = 5 // expect-runtime-error: array 'b' is used before dim or data creates it
