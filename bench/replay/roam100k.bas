// A robot that roams the screen for 100,000 statements: forward until it feels a wall or
// bumps into something, then a turn. Its trail is red, a colour its sensors ignore.
rLocate 400, 300
rInvisible RED
rPen DOWN
for i = 1 to 49998
  if rFeel() or rBumper() then rTurn 77 else rForward 3
next
