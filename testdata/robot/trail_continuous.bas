// The pen trail is one continuous line even when the program draws between two moves (here
// status text): every pixel of the path is drawn.
rLocate 400, 300
rInvisible Green
rPen Down
for i = 1 to 100
  xyString 10, 10, i
  rForward 1
next
rTurn 90
for i = 1 to 50
  xyString 10, 10, i
  LineWidth 1 + i % 2
  rForward 1
next
rPen Up
rForward 50
n = 0
for y = 200 to 300
  if pixelClr(400, y) = Green then n++
next
print n // expect: 101
n = 0
for x = 400 to 450
  if pixelClr(x, 200) = Green then n++
next
print n // expect: 51
print pixelClr(480, 200) = Green // expect: 0
