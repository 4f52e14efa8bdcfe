// A keyboard remote control steered with tmux send-keys by tui_test.py (headless: --keys).
// args: --keys "wwdwq"
rLocate 400, 300
print "w forward, a/d turn, q quits"
repeat
  waitKey k
  if k = ascii("w") then rForward 20
  if k = ascii("a") then rTurn -90
  if k = ascii("d") then rTurn 90
until k = ascii("q")
print "bye at ", rGpsX(), ",", rGpsY()
// expect: w forward, a/d turn, q quits
// expect: bye at 420,260
