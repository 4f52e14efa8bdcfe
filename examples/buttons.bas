// Buttons: the program's own buttons and an edit box.
// Type a size (20 to 250) into the Size box, then press Square or Triangle to have the robot
// draw it; Clear wipes the screen, Quit ends the program.

rLocate 300, 400
rInvisible Green      // the pen's colour: the robot drives over its own lines
lineWidth 3
AddButton "Square", 10, 560
AddButton "Triangle", 90, 560
AddButton "Clear", 180, 560
AddButton "Quit", 250, 560
AddEdit "Size", 380, 560, 60, "120"
xyString 450, 565, "pixels"
shapes = 0

repeat
  b = LastButton()
  if b = "Square" or b = "Triangle"
    size = toNumber(GetEdit("Size"), 0)
    if size < 20 or size > 250
      print "The size must be a number from 20 to 250."
    else
      sides = 3
      if b = "Square" then sides = 4
      gosub DrawShape
      shapes = shapes + 1
      print b, " of ", size, " pixels"
    endif
  endif
  if b = "Clear"
    clearScr
    xyString 450, 565, "pixels"
  endif
  delay 20            // look at the buttons 50 times a second
until b = "Quit"
print "Drawn: ", shapes, " shapes"
end

// A shape of `sides` sides of `size` pixels, back where it started, heading as before.
DrawShape:
  rPen Down
  for n = 1 to sides
    rForward size
    rTurn 360 / sides
  next
  rPen Up
return
