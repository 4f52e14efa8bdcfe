// Text the program draws shows as characters in the live view when its cells are readable.
xyText 40, 200, "HELLO ROBOT", "Courier New", 48, fs_Bold, BLACK, WHITE
print "drawn"
// expect: drawn
