// The robot drives into a red block: the live view shows the error, and rb prints it on exit.
rLocate 400, 300
rectangle 380, 100, 420, 120, Red, Red
rSpeed 1
rForward 300 // expect-runtime-error: robot crashed into an obstacle: colour Red at (400, 120)
