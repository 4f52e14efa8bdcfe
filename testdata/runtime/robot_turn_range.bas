// A turn is bounded (a million degrees): rTurn steps once per degree.
rLocate 400, 300
rTurn 1e300 // expect-runtime-error: argument 1 (degrees) of rTurn is out of range: 1e+300 (allowed: -1000000 to 1000000)
