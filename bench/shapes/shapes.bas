// shapes: 100,000 shapes of random place and size (a linear congruential generator, the same
// in shapes_pil.py): circles, ellipses, rectangles and lines in turn, every other one filled,
// 16 colours. Prints a checksum of a grid of pixels.
seed = 1
for i = 0 to 99999
  seed = (seed * 1103515245 + 12345) % 2147483648
  x = seed % 800
  seed = (seed * 1103515245 + 12345) % 2147483648
  y = seed % 600
  seed = (seed * 1103515245 + 12345) % 2147483648
  w = 4 + seed % 120
  seed = (seed * 1103515245 + 12345) % 2147483648
  h = 4 + seed % 90
  c = i % 16
  k = i % 4
  filled = i % 8 >= 4
  if k = 0
    if filled
      circle x, y, x + w, y + w, c, c
    else
      circle x, y, x + w, y + w, c
    endif
  elseif k = 1
    if filled
      circle x, y, x + w, y + h, c, c
    else
      circle x, y, x + w, y + h, c
    endif
  elseif k = 2
    if filled
      rectangle x, y, x + w, y + h, c, c
    else
      rectangle x, y, x + w, y + h, c
    endif
  else
    line x, y, x + w, y + h, 1, c
  endif
next
sum = 0
for py = 0 to 599 step 7
  for px = 0 to 799 step 5
    sum = sum + pixelClr(px, py)
  next
next
print sum
