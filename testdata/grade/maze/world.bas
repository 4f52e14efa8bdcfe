// The maze: two black walls the robot bumps into, a red lava pool it does not see (rInvisible)
// but must keep out of, and the robot placed at the start facing up.
Rectangle 200, 150, 220, 600, BLACK, BLACK
Rectangle 420, 0, 440, 450, BLACK, BLACK
Rectangle 620, 200, 760, 300, RED, RED
rInvisible RED
rLocate 100, 500, 0
