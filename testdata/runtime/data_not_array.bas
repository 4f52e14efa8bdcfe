d = 5
data d; 1 // expect-runtime-error: data: 'd' is not an array
