// mPolygon with a flat data array, as real programs write it: a pair with a negative x starts a
// polygon (at -x), a pair with a negative y is the point to fill that polygon from (not a
// vertex). The outline is drawn in the current colour and line width, the fill is the colour.
data P; -100,100, 300,100, 300,250, 100,250, 100,100, 200,-175
setColor Black
LineWidth 3
mPolygon P, Blue
print pixelClr(200, 175) = Blue // expect: 1
print pixelClr(100, 175) = Black, pixelClr(99, 175) = Black, pixelClr(101, 175) = Black // expect: 111
print pixelClr(102, 175) = Blue, pixelClr(98, 175) = White // expect: 11
print pixelClr(200, 100) = Black // expect: 1
print pixelClr(400, 400) = White // expect: 1
// Several polygons share one array, each with its own fill point; the fill point (500, 150)
// is not a vertex (the triangle's third corner is (450, 200)).
clearScr
LineWidth 1
data Q; -400,100, 600,100, 450,200, 500,-150, -50,300, 150,300, 150,400, 50,400, -100,-350
mPolygon Q, LightGreen
print pixelClr(500, 130) = LightGreen, pixelClr(100, 350) = LightGreen // expect: 11
print pixelClr(600, 100) = Black, pixelClr(50, 350) = Black // expect: 11
print pixelClr(500, 180) = White, pixelClr(550, 160) = White // expect: 11
// Without a fill point the polygon's inside is filled; without a colour nothing is filled.
clearScr
data T; -100,100, 200,100, 150,200
mPolygon T, Red
print pixelClr(150, 130) = Red, pixelClr(100, 100) = Black // expect: 11
data U; -300,100, 400,100, 350,200, 350,-130
mPolygon U
print pixelClr(350, 130) = White, pixelClr(300, 100) = Black // expect: 11
// The n x 2 form keeps its meaning: rows are vertices, then the outline and fill colours.
clearScr
dim M[3, 2]
M[0, 0] = 100
M[0, 1] = 100
M[1, 0] = 200
M[1, 1] = 100
M[2, 0] = 150
M[2, 1] = 200
mPolygon M, Blue, Yellow
print pixelClr(150, 130) = Yellow, pixelClr(100, 100) = Blue // expect: 11
