// nontest: the robot drives into the screen's edge and into a drawn wall (diagnostics/run.t)
rLocate 400, 300
lineWidth 5
line 380, 200, 420, 200
rForward 200
