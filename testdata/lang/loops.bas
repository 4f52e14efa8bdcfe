// for/next (step, negative step, zero passes), while/wend, repeat/until, break, continue.
total = 0
for i = 1 to 10 step 3
  total = total + i
next
print total // expect: 22
for i = 5 to 1 step -2
  print i; // expect: 5	3	1	
next i
print
for i = 3 to 1
  print "never"
next
print i // expect: 3
for i = 1 to 3
next
print i // expect: 4
for x = 0 to 1 step 0.25
  print x, " ";
next
print // expect: 0 	0.25 	0.5 	0.75 	1 	
n = 0
while n < 3
  n = n + 1
wend
print n // expect: 3
repeat
  n = n - 1
until n = 0
print n // expect: 0
for i = 1 to 10
  if i % 2 = 0 then continue
  if i > 7 then break
  print i; // expect: 1	3	5	7	
next
print
k = 0
while true
  k++
  if k < 3 then continue
  break
wend
print k // expect: 3
r = 0
repeat
  r++
  if r = 2 then continue
until r >= 4
print r // expect: 4
for i = 1 to 3
  for j = 1 to 3
    if j = 2 then break
    print i, j; // expect: 11	21	31	
  next
next
print
lim = 3
for i = 1 to lim
  lim = 10
next
print i // expect: 4
