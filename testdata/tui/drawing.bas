// Draws and prints nothing: headless on a terminal, rb says where the picture is
// (tui_test.py draw_hint); with the output piped, as here, it says nothing.
rLocate 400, 300
rPen DOWN
rForward 100
Circle 100, 100, 200, 200, RED
