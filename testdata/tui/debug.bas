// Stepping, breakpoints and the variables pane: tui_test.py runs it with --paused and --break.
total = 0
name = "rb"
dim marks[4]
for n = 1 to 3
  gosub AddOne
  marks[n] = total
next
print "total ", total
end

AddOne:
  total = total + n
  return
// expect: total 6
