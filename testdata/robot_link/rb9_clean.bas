// Figure 1.13 with the simulator chosen: nothing in it or in RB-9.bas troubles the RB-9.
// check-args: --target rb9
#include "RB-9.bas"
gosub InitRROscommands

Real = FALSE // set to FALSE to use simulator
PortNum = 5 // set variable to your Bluetooth Port Number

Main:
  if Real
    gosub InitializeRealRobot
  else
    gosub RB9_InitializeSimulator
  endif
  gosub DrawSquare
  print "done"  // expect: done
end

DrawSquare:
  for n = 1 to 4
    rForward 120
    rTurn 90
  next
return
