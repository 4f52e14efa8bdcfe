// Robot statements where the robot may be placed: rb check says nothing.
goto Start // past the routines, as a library does

Place:
  rLocate 400, 300
  placed = 1
return

Start:
gosub Place
rForward 10
rTurn 90

// After a sub that places it (called as a statement or in an expression).
call Again(300)
rForward 10
n = Again(300)
print rCompass() // expect: 0

// Placed in one branch only: the other way may not reach the sensor unplaced, but one may
// be placed, so nothing is said.
if placed = 1
  rLocate 400, 300
endif
if rFeel() = 0 then rForward 5

// A loop whose first pass places the robot before it moves.
for i = 1 to 2
  if i = 2 then rForward 5
  if i = 1 then rLocate 400, 300
next
print "done" // expect: done
end

sub Again(y)
  rLocate 400, y
  return y
endsub
