// Heading 0 is up, clockwise positive; compass 0..359; GPS is the centre, rounded.
rLocate 100.4, 200.6
print rGPSX(), ",", rGPSY() // expect: 100,201
rTurn -90
print rCompass() // expect: 270
rTurn 450
print rCompass() // expect: 0
rTurn 45
rForward 100
print rGPSX(), ",", rGPSY() // expect: 171,130
print rChargeLevel() // expect: 99
rForward -100
print rGPSX(), ",", rGPSY() // expect: 100,201
