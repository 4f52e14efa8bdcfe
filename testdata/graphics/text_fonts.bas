// Text looks like RobotBASIC's screen: print and xyString use a Courier-like monospaced face
// (Liberation Mono, Courier New's metrics) at 10 points, 8 x 15 pixels a character: 100
// columns, 40 lines. A background colour fills the characters' cells, which shows them.
// (What print shows goes on the screen too: the checks are read before they are printed.)
setColor black, yellow
print "#" // expect: #
print "#" // expect: #
a = pixelClr(0, 0) = Yellow and pixelClr(7, 29) = Yellow
b = pixelClr(8, 0) = White and pixelClr(0, 30) = White
print a, b // expect: 11
// The fourth line (rows 45 to 59) fills the whole width with 100 characters.
s = ""
for i = 1 to 10
  s = s + "0123456789"
next
print s // expect: 0123456789012345678901234567890123456789012345678901234567890123456789012345678901234567890123456789
print pixelClr(799, 45) = Yellow, pixelClr(799, 59) = Yellow, pixelClr(0, 60) = White // expect: 111
// xyString draws with the same font at any point.
xyString 300, 300, "##"
print pixelClr(315, 314) = Yellow, pixelClr(316, 300) = White, pixelClr(300, 315) = White // expect: 111

// xyText x, y, text, font, size (points), style, colour, background. Size 24 points is a 32
// pixel em: Courier's cell is then 19 x 37 pixels.
xyText 100, 400, " ", "", 24, 0, black, yellow
print pixelClr(118, 436) = Yellow, pixelClr(119, 400) = White, pixelClr(100, 437) = White // expect: 111
// Font names map to faces with Windows' widths: "Hello, World" at 10 points is 96 pixels in
// Courier New (12 x 8), narrower in Arial and Times New Roman.
sub TextWidth(name, y)
  xyText 100, y, "Hello, World", name, 10, 0, black, yellow
  w = 0
  while pixelClr(100 + w, y) <> White
    w = w + 1
  wend
  return w
endsub
clearScr
print TextWidth("Courier New", 100) // expect: 96
print TextWidth("Arial", 150) // expect: 71
print TextWidth("Times New Roman", 200) // expect: 68
print TextWidth("", 250) // expect: 96
