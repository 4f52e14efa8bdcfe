rLocate 400,300
for n = 1 to 4
  rForward 120
  rTurn 90
next
