// rLocate's coordinates are bounded like every robot distance.
rLocate 1e18, 300 // expect-runtime-error: argument 1 (x) of rLocate is out of range: 1e+18 (allowed: -1000000 to 1000000)
