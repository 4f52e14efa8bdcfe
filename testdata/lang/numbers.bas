// Integers and doubles are kept apart; integral results print without a decimal point.
print 7/2 // expect: 3.5
print 6/2 // expect: 3
print 1/3 // expect: 0.333333333333333
print 2.50 // expect: 2.5
print 0.1 + 0.2 // expect: 0.3
print 10 * 1.5 // expect: 15
print .5 // expect: 0.5
print 1e3 // expect: 1000
print 1.5e-3 // expect: 0.0015
print 0x1F // expect: 31
print -5 // expect: -5
print 9223372036854775807 + 1 // expect: 9.22337203685478e+18
print 2 ^ 10 // expect: 1024
print 2 ^ 0.5 // expect: 1.4142135623731
print 2 ^ -1 // expect: 0.5
print 7 % 3 // expect: 1
print 7 mod 3 // expect: 1
print -7 % 3 // expect: -1
print 7.5 % 2 // expect: 1.5
print 1e20 // expect: 1e+20
x = 3
x = x / 2
print x // expect: 1.5
print true, false, up, down // expect: 1001
