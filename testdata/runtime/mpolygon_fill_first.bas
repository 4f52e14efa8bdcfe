data P; 100,-100, 200,100, 300,100
mPolygon P, Red // expect-runtime-error: argument 1 (points) of mPolygon has a fill point (negative y) before any polygon
