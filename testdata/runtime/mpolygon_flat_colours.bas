data P; -100,100, 200,100, 150,200
mPolygon P, Red, Blue // expect-runtime-error: mPolygon with a flat array takes one colour, the fill: argument 3 (fill) of mPolygon is one too many
