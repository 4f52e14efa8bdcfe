// Keywords, commands, functions and constants ignore case; variables and labels do not.
a = 1
A = 2
PRINT a // expect: 1
Print A // expect: 2
pRiNt a + A // expect: 3
print ABS(-3) + abs(-1) // expect: 4
print RED, red, Red // expect: 444
IF a = 1 THEN PRINT "yes" // expect: yes
GoSub Lower
goSUB Upper
END
Lower:
  print "lower" // expect: lower
RETURN
Upper:
  print "Upper" // expect: Upper
return
