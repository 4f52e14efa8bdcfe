// 65,536 corners is the most one polygon statement draws: this one is drawn.
dim p[131072]
for i = 0 to 131071 step 2
  p[i] = 400 + 300 * cos(i / 131072 * 2 * pi())
  p[i + 1] = 300 + 200 * sin(i / 131072 * 2 * pi())
next
polygon p, red
print pixelclr(700, 300) // expect: 4
