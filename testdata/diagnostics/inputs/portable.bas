// nontest: rb check --portable's warnings and their notes (portable.t)
x = rtod(1)
s = trimL(" a")
if s = "a" then print x else print s
for i = 1 to 3 step 2
next
