// A correct square written another way: a subroutine draws one side. The student's own test:
// expect: perimeter 480
rLocate 400, 300
rInvisible GREEN
LineWidth 4
rPen DOWN
side = 120
gosub Side
gosub Side
gosub Side
gosub Side
print "perimeter " + 4 * side
end

Side:
  rForward side
  rTurn 90
return
