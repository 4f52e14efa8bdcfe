// Driving into an obstacle stops the program at the moving statement.
rectangle 380, 100, 420, 200, blue, blue
rLocate 400, 300
print "before" // expect: before
rForward 200 // expect-runtime-error: robot crashed into an obstacle: colour Blue at (400, 200)
print "after"
