// A robot that roams the screen for 10,000,000 statements, a pixel per move: forward until it
// feels a wall, then a turn. Its trail is red, a colour its sensor ignores.
rLocate 400, 300
rInvisible RED
rPen DOWN
for i = 1 to 4999998
  if rFeel() then rTurn 77 else rForward 1
next
