// Moves and turns beyond one byte: link_tests.py checks that they reach the robot emulator as
// several commands (600 = 255 + 255 + 90, 400 = 255 + 145).
rLocate 400,300
rTurn 400
rTurn -400
rTurn 90
rLocate 100,300,90
rForward 600
print rGPSX() + " " + rGPSY()
// expect: 700 300
