// Arrays are global wherever they are dimmed, and every sub sees them by their plain names (a
// SERVO Magazine program by RobotBASIC's authors dims arrays in one sub and reads them in the
// main program and in another sub). Scalars in a sub stay local; a parameter is that sub's own
// name even when an array elsewhere has the same name.
call Setup(3)
print Grid[1, 2]
// expect: 3
print MaxDim(Grid, 2)
// expect: 3
call Fill()
print Grid[0, 0]; Grid[1, 1]
// expect: 7	7
n = 100
call Count()
print n
// expect: 100
data Names; "a", "b"
call Show(Names)
// expect: 2 a
Table = 5
print Table
// expect: 5
end

sub Setup(size)
  dim Grid[2, size]
  Grid[1, 2] = size
  n = 1
return

sub Fill()
  for i = 0 to 1
    Grid[i, i] = 7
  next
return

sub Count()
  n = 0
return

sub Show(Grid)
  print MaxDim(Grid, 1), " ", Grid[0]
return
