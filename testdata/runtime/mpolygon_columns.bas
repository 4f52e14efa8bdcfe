dim p[3, 3]
mPolygon p // expect-runtime-error: argument 1 (points) of mPolygon must be an array with 2 columns (x, y)
