// rLook and rBeacon see a red disc; invisible colours are looked through for the beacon.
circle 600, 280, 640, 320, red, red
rLocate 400, 300
print rLook(90) // expect: 4
print rLook() // expect: 0
print rBeacon(RED) // expect: 0
rTurn 90
print rBeacon(RED) // expect: 181
rectangle 500, 250, 510, 350, green, green
print rBeacon(RED) // expect: 0
rInvisible GREEN
print rBeacon(RED) // expect: 181
print rBeacon(GREEN) // expect: 81
rTurn -90
h = 0
while rBeacon(RED) = false
  rTurn 1
  h = h + 1
wend
print h >= 84 and h <= 96 // expect: 1
