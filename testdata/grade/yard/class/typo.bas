// Kofi: a typo.
input "How many sides? ", n
rLocate 400, 300
rInvisible GREEN
rPen DOWN
for i = 1 to n
  rFoward 120
  rTurn 90
next
print "sides: " + n
print "perimeter: " + n * 120
