// One polygon statement draws at most 65,536 corners: filling costs the corners times the
// screen's rows, and a bound keeps one statement within what a time limit allows.
dim p[131074]
for i = 0 to 131073 step 2
  p[i] = i % 800
  p[i + 1] = (i * 7) % 600
next
polygon p, red // expect-runtime-error: argument 1 (points) of polygon has 65537 corners; at most 65536 are drawn in one statement
