// A menu of buttons and an edit box: the program polls GetButton; Forward drives as many pixels
// as the Steps box says. Buttons and edit boxes are not drawn into the screen's pixels, so the
// robot never senses them (the Forward button sits right in its path).
// args: --events button_menu.events
rLocate 400, 300
AddButton "Forward", 380, 100
AddButton "Left", 10, 10
AddButton "Right", 80, 10, 60, 30
AddButton "Quit", 150, 10
AddEdit "Steps", 10, 50, 80, "10"
repeat
  GetButton b
  if b = "Forward" then rForward toNumber(GetEdit("Steps"))
  if b = "Left" then rTurn -90
  if b = "Right" then rTurn 90
  if b <> "" then print b, ": ", rGpsX(), ",", rGpsY(), " heading ", rCompass()
until b = "Quit"
RemoveButton "Quit"
print "bumper ", rBumper(), ", pixel under the Forward button ", pixelClr(390, 110)
// expect: Forward: 400,290 heading 0
// expect: Forward: 400,170 heading 0
// expect: Right: 400,170 heading 90
// expect: Forward: 520,170 heading 90
// expect: Quit: 520,170 heading 90
// expect: bumper 0, pixel under the Forward button 15
