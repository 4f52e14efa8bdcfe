// Expressions: constants are shared and folded signs stay constants, temporaries are reused
// per statement, and/or give 0 or 1, comparisons give 0 or 1.
a = 2
b = -3.5
c = a * (a + 1) - b / 2
s = "n=" + c
t = a < 3
u = a > 1 and b > 0 or not c
print c; s; t; u // expect: 7.75	n=7.75	1	0
