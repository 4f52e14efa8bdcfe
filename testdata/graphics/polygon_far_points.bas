// Polygon points far outside the screen (beyond a 32-bit integer) are clamped like every other
// coordinate: no overflow, and the statement takes no time (issue 14: it once ran 9 minutes).
// timeout: 5
data p; 2147483648, 0, 4, 0, 4, 2147483648
polygon p, red, red
data q; -1e300, 10, 20, 10, 20, 1e300, 10, 20
polygon q, green, green
a = pixelClr(300, 300) = red
b = pixelClr(15, 300) = green
print a, " ", b
// expect: 1 1
