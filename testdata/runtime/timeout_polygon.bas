// args: --timeout 0.5
// The time limit is looked at between the edges of a polygon's outline: 65,536 edges across the
// screen, 100 pixels wide, take half an hour to draw.
dim p[131072]
for i = 0 to 65535
  p[2 * i] = 799 * (i % 2)
  p[2 * i + 1] = 599 * (i % 2)
next
lineWidth 100
polygon p // expect-runtime-error: stopped after 0.5 seconds (the --timeout limit)
