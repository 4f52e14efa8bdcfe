lineWidth 0 // expect-runtime-error: argument 1 (width) of lineWidth must be a line width from 1 to 100
