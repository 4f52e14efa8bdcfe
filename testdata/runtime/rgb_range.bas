c = RGB(300, 0, 0) // expect-runtime-error: argument 1 (red) of RGB() must be from 0 to 255
