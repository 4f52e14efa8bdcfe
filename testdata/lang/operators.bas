// BASIC and C-style operators with the documented precedence.
print 2 + 3 * 4 // expect: 14
print (2 + 3) * 4 // expect: 20
print 2 * 3 ^ 2 // expect: 18
print 2 ^ 3 ^ 2 // expect: 512
print -2 ^ 2 // expect: 4
print 10 - 4 - 3 // expect: 3
print 12 / 2 / 3 // expect: 2
print 1 + 2 = 3 // expect: 1
print 5 & 3 // expect: 1
print 5 | 3 // expect: 7
print 1 << 4 // expect: 16
print 256 >> 2 // expect: 64
print ~0 // expect: -1
print 6 & 3 = 2 // expect: 1
print 1 | 2 & 0 // expect: 1
print 1 = 1 and 2 = 2 // expect: 1
print 1 = 2 or 2 = 2 // expect: 1
print 1 && 0 // expect: 0
print 0 || 3 // expect: 1
print not 0 // expect: 1
print !5 // expect: 0
print not 1 = 0 // expect: 1
print not (1 = 0) // expect: 1
print not 2 = 0 // expect: 1
print 3 == 3 // expect: 1
print 3 != 3 // expect: 0
print 3 <> 4 // expect: 1
print 2 <= 2, 2 >= 3, 1 < 2, 1 > 2 // expect: 1010
a = 5
b = a = 5
print b // expect: 1
x = 1
x += 4
print x // expect: 5
x -= 2
print x // expect: 3
x *= 10
print x // expect: 30
x /= 4
print x // expect: 7.5
i = 0
i++
i++
i--
print i // expect: 1
