// args: --timeout 0.5
// The time limit is looked at between the edges of mPolygon's outlines and between its
// polygons (a flat array): 13,107 polygons of four edges across the screen, 100 pixels wide,
// each filled from a point, take many minutes to draw.
dim p[131070]
for k = 0 to 131069 step 10
  p[k] = -1
  p[k + 1] = 0
  p[k + 2] = 799
  p[k + 3] = 599
  p[k + 4] = 0
  p[k + 5] = 599
  p[k + 6] = 799
  p[k + 7] = 0
  p[k + 8] = 400
  p[k + 9] = -300
next
lineWidth 100
mPolygon p, blue // expect-runtime-error: stopped after 0.5 seconds (the --timeout limit)
