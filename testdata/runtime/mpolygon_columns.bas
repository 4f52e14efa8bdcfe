dim p[3, 3]
mPolygon p // expect-runtime-error: argument 1 (points) of mPolygon must be a flat array of x, y pairs or an array with 2 columns (x, y)
