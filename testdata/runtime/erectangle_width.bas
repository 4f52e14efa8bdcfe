eRectangle 10, 10, 50, 50, 0, red // expect-runtime-error: argument 5 (width) of eRectangle must be a line width from 1 to 100
