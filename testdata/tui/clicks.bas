// Prints left clicks until a right click or a press of the Stop button; tui_test.py clicks in
// tmux (headless: --events).
// args: --events clicks.events
AddButton "Stop", 700, 20
last = 0
repeat
  readMouse x, y, b
  if b = 1 and last <> 1 then print "left ", x, ",", y
  last = b
  GetButton name
  delay 20
until b = 2 or name = "Stop"
print "end by ", b, " ", name
// expect: left 200,150
// expect: end by 1 Stop
