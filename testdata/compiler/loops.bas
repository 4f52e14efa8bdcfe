// Loops: for keeps its limit and step in hidden slots (a loop without a step, or with step 1,
// ends in ForLoop1, which does not read the step); while tests at the bottom; repeat jumps
// back while its condition is false; break and continue jump to the exit and the test.
total = 0
for i = 1 to 10 step 3
  if i = 7 then continue
  total += i
next
for i = 1 to 2
  total += i
next
n = 0
while n < 100
  n++
  if n >= 3 then break
wend
repeat
  n--
until n <= 0
print total; n // expect: 18	0
