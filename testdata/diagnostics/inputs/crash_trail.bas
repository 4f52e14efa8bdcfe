// nontest: the robot backs into its own pen trail (diagnostics/run.t)
rLocate 200, 300, 90
rPen down
rForward 100
rForward -1
