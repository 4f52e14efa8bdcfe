// Hana: goes round and round.
input "How many sides? ", n
rLocate 400, 300
rInvisible GREEN
rPen DOWN
while 1
  rForward 120
  rTurn 90
wend
print "sides: " + n
