// Binary literals 0%1010 (RobotBASIC course slides: 0%110101 is 53) beside hex 0x1F; `%` with
// anything else before it, or with a space after, stays modulo.
print 0%110101
// expect: 53
print 0%0 + 0%1 + 0%10
// expect: 3
print 0x1F + 0%1111
// expect: 46
print 10%4
// expect: 2
x = 9
print x%5
// expect: 4
print 0 % 2
// expect: 0
print 0%111111111111111111111111111111111111111111111111111111111111111
// expect: 9223372036854775807
