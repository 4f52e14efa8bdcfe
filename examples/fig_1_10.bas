
Main:
  gosub InitializeSimulator
  gosub DrawSquare
end

InitializeSimulator:  
  rLocate 400,300  
  rInvisible GREEN  
  LineWidth 4  
  rPen DOWN  
  rSlip 15 // produces up to 15% random error  
return

DrawSquare:
  for n = 1 to 4
    rForward 120
    rTurn 90
  next
return

