xyText 10, 10, "a", "Arial", 500 // expect-runtime-error: argument 5 (size) of xyText must be a font size from 1 to 200
