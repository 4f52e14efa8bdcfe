// args: --timeout 0.5
// The time limit is looked at between the edges of mPolygon's outline (an array of rows x, y):
// 65,536 edges across the screen, 100 pixels wide, take half an hour to draw.
dim p[65536, 2]
for i = 0 to 65535
  p[i, 0] = 799 * (i % 2)
  p[i, 1] = 599 * (i % 2)
next
lineWidth 100
mPolygon p, red // expect-runtime-error: stopped after 0.5 seconds (the --timeout limit)
