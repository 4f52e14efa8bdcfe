// print: ',' joins items, ';' puts a tab between them, a trailing separator keeps the line.
print "a", "b" // expect: ab
print "a"; "b" // expect: a	b
print 1, 2; 3 // expect: 12	3
print "no newline",
print " here" // expect: no newline here
print "tab after";
print "x" // expect: tab after	x
print(5) // expect: 5
print (1 + 2) * 3 // expect: 9
print // expect:
print "end" // expect: end
