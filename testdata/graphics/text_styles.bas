// xyText's style: the constants fs_Bold, fs_Italic, fs_Underline and fs_StrikeOut, added or
// or-ed together (or the letters "b", "i", "u", "s"); font "" is the default face.
print fs_Bold, " ", fs_Italic, " ", fs_Underline, " ", fs_StrikeOut // expect: 1 2 4 8
print fs_Bold + fs_Italic, " ", fs_Bold | fs_Underline // expect: 3 5
clearScr

// The pixels a text draws in its 200 x 40 box at (x, y), and the rows that hold any.
sub Ink(x, y)
  n = 0
  for yy = y to y + 39
    for xx = x to x + 199
      if pixelClr(xx, yy) <> White then n = n + 1
    next
  next
  return n
endsub
sub InkRows(x, y)
  rows = 0
  for yy = y to y + 39
    for xx = x to x + 199
      if pixelClr(xx, yy) <> White
        rows = rows + 1
        break
      endif
    next
  next
  return rows
endsub

xyText 0, 0, "Robot", "", 14
xyText 200, 0, "Robot", "", 14, fs_Bold
xyText 400, 0, "Robot", "", 14, "b"
plain = Ink(0, 0)
bold = Ink(200, 0)
print bold > plain, Ink(400, 0) = bold // expect: 11
// Italic: the Liberation Mono Italic face, another shape.
xyText 0, 100, "Robot", "", 14, fs_Italic
xyText 200, 100, "Robot", "", 14, fs_Bold | fs_Italic
print Ink(0, 100) <> plain, Ink(200, 100) <> bold // expect: 11
// Underline and strike-out are lines across the text; spaces show them alone.
xyText 0, 200, "     ", "Arial", 14, fs_Underline
xyText 200, 200, "     ", "Arial", 14, fs_StrikeOut
xyText 400, 200, "     ", "Arial", 14, fs_Underline + fs_StrikeOut
xyText 600, 200, "     ", "Arial", 14, "us"
print Ink(0, 200) > 0, Ink(200, 200) > 0 // expect: 11
print InkRows(400, 200) = InkRows(0, 200) + InkRows(200, 200), Ink(600, 200) = Ink(400, 200) // expect: 11
// The underline lies below the strike-out line.
sub FirstRow(x, y)
  for yy = y to y + 39
    if pixelClr(x + 2, yy) <> White then return yy
  next
  return -1
endsub
print FirstRow(0, 200) > FirstRow(200, 200) // expect: 1
// Style 0 and "" are plain; the default face is the print font's.
xyText 0, 300, "Robot", "", 14, 0
xyText 200, 300, "Robot", "Courier New", 14, ""
print Ink(0, 300) = plain, Ink(200, 300) = plain // expect: 11
