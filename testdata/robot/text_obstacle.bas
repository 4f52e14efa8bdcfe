// Text is drawn with a real font into the screen, so the robot senses it like any drawing: its
// rays hit the letters' pixels (and pass through the gaps between them).
xyText 360, 150, "WALL", "", 24, fs_Bold, red
rLocate 400, 300
hits = 0
for a = -10 to 10
  if rRange(a) < 140 and rLook(a) = Red then hits = hits + 1
next
print hits > 10 // expect: 1
// Seen from below the gap between two letters, the ray goes on to the screen's edge.
misses = 0
for a = -10 to 10
  if rLook(a) = 0 then misses = misses + 1
next
print misses > 0 // expect: 1
