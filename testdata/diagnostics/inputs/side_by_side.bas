// nontest: two values side by side, the missing operator's fix-its (diagnostics/check.t)
n = 5
print "reached in " + n " moves"
msg = "x = "n
total = 2 n
total = (n + 1) n
print n 2
