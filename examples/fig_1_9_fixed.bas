
Main:
  gosub InitializeSimulator
  gosub DrawSquare
end

InitializeSimulator:
  rLocate 300,500
  rInvisible GREEN
  LineWidth 4
  rPen DOWN
return

DrawSquare:
  for n = 1 to 4
    rForward 120
    rTurn 90
  next
return

