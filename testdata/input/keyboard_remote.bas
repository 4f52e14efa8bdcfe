// A keyboard remote control in the style of lab 3's holdToMoveControl: each key moves the robot
// once; q quits. The keys come from --keys, one press per character.
// args: --keys "wwdwwaasq"
rLocate 400, 300
rInvisible Green
rPen down
print "w/s move, a/d turn, q quits"
repeat
  waitKey k
  if k = ascii("w") then rForward 20
  if k = ascii("s") then rForward -20
  if k = ascii("a") then rTurn -90
  if k = ascii("d") then rTurn 90
until k = ascii("q")
print "at ", rGpsX(), ",", rGpsY(), " heading ", rCompass()
// expect: w/s move, a/d turn, q quits
// expect: at 460,260 heading 270
