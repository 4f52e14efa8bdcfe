// nontest: rb check --portable's warnings and their notes (portable.t)
x = kc_Enter + rtod(1)
line 1, 2, 3, 4
if x > 1 then print x else print 0
for i = 1 to 3 step 2
next
