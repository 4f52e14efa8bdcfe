// Lab 3's holdToMoveControl: waitKey returns at once while a key is held, so holding a key keeps
// the robot moving. The prompt is printed once: waitKey does not print the same prompt again
// while it is still the last thing printed.
// args: --events hold_to_move.events
rLocate 400, 300
rSpeed 2
while true
  waitKey "Hold h, n, v or b (q quits) ", key
  if key = ascii("h")
    rForward 5
  elseif key = ascii("n")
    rTurn 5
  elseif key = ascii("v")
    rTurn -5
  elseif key = ascii("b")
    rForward -5
  elseif key = ascii("q")
    break
  endif
wend
print
print "at ", rGpsX(), ",", rGpsY(), " heading ", rCompass()
// expect: Hold h, n, v or b (q quits) 
// expect: at 400,250 heading 90
