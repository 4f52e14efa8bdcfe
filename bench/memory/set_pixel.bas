// set_pixel: 1,000,000 setPixel calls over the whole screen in 16 colours, then a checksum of
// some of the pixels (pixelClr).
n = 1000000
for i = 0 to n - 1
  setPixel i % 800, (i / 800) % 600, i % 16
next
sum = 0
for y = 0 to 599 step 7
  for x = 0 to 799 step 5
    sum = sum + pixelClr(x, y)
  next
next
print sum
