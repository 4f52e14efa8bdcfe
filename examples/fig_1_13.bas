
#include "RB-9.bas"
gosub InitRROscommands

Real = TRUE // set to FALSE to use simulator
PortNum = 5 // set variable to your Bluetooth Port Number

Main:
  if Real
    gosub InitializeRealRobot
  else
    gosub InitializeSimulator
  endif
  gosub DrawSquare
end

InitializeSimulator:
  rLocate 400,300
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

