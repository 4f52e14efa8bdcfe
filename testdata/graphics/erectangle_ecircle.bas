// eRectangle and eCircle take the corners of their box, like rectangle and circle, and draw only
// an edge of the given width (growing inward) in the given colour: no fill. A published menu
// draws a cyan panel, then a white frame 2 pixels wide just inside it.
rectangle 50, 50, 750, 550, cyan, cyan
eRectangle 52, 52, 750, 550, 2, white
print pixelClr(400, 300) = Cyan // expect: 1
print pixelClr(400, 51) = Cyan // expect: 1
print pixelClr(400, 52) = White // expect: 1
print pixelClr(400, 53) = White // expect: 1
print pixelClr(400, 54) = Cyan // expect: 1
print pixelClr(749, 300) = White // expect: 1
print pixelClr(748, 300) = Cyan // expect: 1
print pixelClr(20, 20) = White // expect: 1
// The corners may come in any order.
clearScr
eRectangle 300, 200, 100, 100, 3, red
print pixelClr(100, 150) = Red, pixelClr(102, 150) = Red, pixelClr(103, 150) = White // expect: 111
print pixelClr(300, 200) = Red, pixelClr(200, 150) = White // expect: 11
// Width and colour default to the line width and the current colour.
clearScr
setColor blue
lineWidth 4
eRectangle 10, 10, 60, 60
print pixelClr(13, 30) = Blue, pixelClr(14, 30) = White // expect: 11
// eCircle: the ring of the ellipse inscribed in the box, inward.
clearScr
eCircle 100, 100, 200, 200, 3, red
print pixelClr(100, 150) = Red, pixelClr(102, 150) = Red, pixelClr(103, 150) = White // expect: 111
print pixelClr(150, 199) = Red, pixelClr(150, 150) = White, pixelClr(99, 150) = White // expect: 111
eCircle 300, 100, 500, 200
print pixelClr(300, 150) = Blue, pixelClr(303, 150) = Blue, pixelClr(304, 150) = White // expect: 111
