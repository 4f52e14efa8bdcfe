data p; 1, 2, "x", 4
polygon p // expect-runtime-error: argument 1 (points) of polygon holds something that is not a number
