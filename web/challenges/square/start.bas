// Draw a square with sides of 120 pixels, clockwise, from 400, 300.
rLocate 400,300
rPen DOWN
rForward 120
