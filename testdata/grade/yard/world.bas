// The yard every run starts in: a red flower bed right of the square. The robot is placed by
// the student's program (rLocate), as in the seed's Figure 1.7.
Rectangle 580, 120, 700, 330, RED, RED
xyText 600, 340, "flowers", "", 10
