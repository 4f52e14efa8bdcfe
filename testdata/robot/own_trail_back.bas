// The pen trail in an obstacle colour: driving on, turning on it and driving off it are free;
// backing up along the trail just drawn runs into it at once (the rear of the rim leads).
rLocate 200, 300, 90
rPen down
rForward 300
print rGPSX() // expect: 500
rTurn 90
rTurn -180
rForward 40
print rGPSY() // expect: 260
rForward -1 // expect-runtime-error: robot crashed into an obstacle: its own pen trail (colour Black); add 'rInvisible Black' before 'rPen down' so the robot does not see its trail
