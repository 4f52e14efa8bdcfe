polygon 5 // expect-runtime-error: argument 1 (points) of polygon must be an array of coordinates
