// A program without "end" stops at the end of the file; falling into a label is normal.
mainProgram:
print "start" // expect: start
Later:
print "later" // expect: later
