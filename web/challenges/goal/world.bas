// The world: a black wall in the middle the robot bumps into, a green goal at the top right,
// and the robot at the bottom left facing up.
Rectangle 380, 150, 400, 600, BLACK, BLACK
Rectangle 600, 60, 760, 160, GREEN, GREEN
rInvisible GREEN
rLocate 100, 500, 0
