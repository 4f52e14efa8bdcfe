// Strings: double quotes, no escapes, + concatenates (numbers too), comparisons.
s = "Hello" + " " + "World"
print s // expect: Hello World
print "x=" + 5 // expect: x=5
print 5 + "x" // expect: 5x
print "a\b" // expect: a\b
print "1.5" + 2.5 // expect: 1.52.5
print "abc" < "abd" // expect: 1
print "abc" = "abc" // expect: 1
print "B" > "a" // expect: 0
print "5" = 5 // expect: 0
print "5" <> 5 // expect: 1
print "" // expect:
