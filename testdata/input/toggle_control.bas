// Lab 3's toggleControl, steered by getKey (a non-blocking read of the key held now): a press of
// h starts or stops driving forward, n and v turn; q quits (added so that the program ends).
// The events file holds each key for a while of virtual time, the way a person would.
// args: --events toggle_control.events
rLocate 400, 300
prevKey = 0
lastValidKey = 0
status = 0
while true
  getKey key
  if key <> 0 and key <> prevKey
    if key = ascii("q") then break
    if key = ascii("h") or key = ascii("n") or key = ascii("v")
      lastValidKey = key
      status = 1 - status
    endif
  endif
  prevKey = key
  if status
    if lastValidKey = ascii("h")
      rForward 5
    elseif lastValidKey = ascii("n")
      rTurn 5
    elseif lastValidKey = ascii("v")
      rTurn -5
    endif
  endif
  delay 10
wend
print "at ", rGpsX(), ",", rGpsY(), " heading ", rCompass()
// expect: at 400,200 heading 90
