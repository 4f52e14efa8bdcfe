// A maze: the program builds a new maze of 8 x 6 rooms every run, then the robot finds its way
// from the top left room to the green room at the bottom right, using only its range sensor:
// it keeps a wall on its right hand (take a way to the right if there is one, else straight
// on, else to the left, else turn back). In a maze like this that always finds the way out.

cols = 8
rows = 6
size = 100            // pixels a room

// ---- Build the maze: a random walk that never enters a room twice, backing up where it is
// stuck (a "recursive backtracker"). openRight and openDown say where a wall was taken away.
dim seen[cols, rows], openRight[cols, rows], openDown[cols, rows]
dim pathC[cols * rows], pathR[cols * rows]
pathC[0] = 0
pathR[0] = 0
seen[0, 0] = True
top = 0
while top >= 0
  c = pathC[top]
  r = pathR[top]
  gosub CountFreeNeighbours
  if free = 0
    top = top - 1     // stuck: back up
  else
    pick = random(free)
    gosub OpenNeighbour
    top = top + 1
    pathC[top] = c
    pathR[top] = r
    seen[c, r] = True
  endif
wend

// ---- Draw it: the walls in black, the goal room in green.
rectangle (cols - 1) * size + 8, (rows - 1) * size + 8, cols * size - 8, rows * size - 8, Green, Green
setColor Black
lineWidth 4
rectangle 0, 0, 799, 599
for c = 0 to cols - 1
  for r = 0 to rows - 1
    x = c * size
    y = r * size
    if c < cols - 1 and not openRight[c, r]
      gotoXY x + size, y
      lineTo x + size, y + size
    endif
    if r < rows - 1 and not openDown[c, r]
      gotoXY x, y + size
      lineTo x + size, y + size
    endif
  next
next

// ---- Find the way out, keeping a wall on the right.
rLocate size / 2, size / 2, 90
rInvisible LightBlue, Green  // the pen's colour and the goal room: not walls
lineWidth 3
rPen Down
goalX = cols * size - size / 2
goalY = rows * size - size / 2
moves = 0
while not (rGPSX() = goalX and rGPSY() = goalY)
  if rRange(90) > size / 2
    rTurn 90          // a way to the right
  else
    if rRange(0) < size / 2
      if rRange(-90) > size / 2
        rTurn -90     // blocked ahead: left
      else
        rTurn 180     // a dead end: back
      endif
    endif
  endif
  rForward size
  moves = moves + 1
wend
print "Out of the maze in ", moves, " moves"
end

// How many rooms next to room (c, r) have not been seen yet: `free`.
CountFreeNeighbours:
  free = 0
  if c > 0 and not seen[c - 1, r] then free = free + 1
  if c < cols - 1 and not seen[c + 1, r] then free = free + 1
  if r > 0 and not seen[c, r - 1] then free = free + 1
  if r < rows - 1 and not seen[c, r + 1] then free = free + 1
return

// Takes away the wall to the unseen room number `pick` (0 .. free - 1) next to (c, r) and
// moves (c, r) there.
OpenNeighbour:
  if c > 0 and not seen[c - 1, r]
    if pick = 0
      c = c - 1
      openRight[c, r] = True
      return
    endif
    pick = pick - 1
  endif
  if c < cols - 1 and not seen[c + 1, r]
    if pick = 0
      openRight[c, r] = True
      c = c + 1
      return
    endif
    pick = pick - 1
  endif
  if r > 0 and not seen[c, r - 1]
    if pick = 0
      r = r - 1
      openDown[c, r] = True
      return
    endif
    pick = pick - 1
  endif
  openDown[c, r] = True
  r = r + 1
return
