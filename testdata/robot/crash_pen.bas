// With the pen down and no invisible colour the robot sees its own trail (the seed warns).
rLocate 400, 300
rPen down
rForward 10 // expect-runtime-error: robot crashed into an obstacle
