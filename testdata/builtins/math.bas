// Math built-ins; angles in radians.
print abs(-7), " ", abs(2.5) // expect: 7 2.5
print sqrt(16), " ", sqrt(2) // expect: 4 1.4142135623731
print round(sin(pi() / 2)), " ", round(cos(0)) // expect: 1 1
print tan(0), " ", atan(1) * 4 // expect: 0 3.14159265358979
print asin(1) * 2, " ", acos(1) // expect: 3.14159265358979 0
print atan2(1, 0) * 2 // expect: 3.14159265358979
print exp(0), " ", ln(exp(2)), " ", log(1000) // expect: 1 2 3
print pow(2, 8), " ", pow(4, 0.5) // expect: 256 2
print int(3.7), " ", int(-3.7), " ", floor(-3.2), " ", ceil(3.2) // expect: 3 -3 -4 4
print frac(3.25), " ", round(2.5), " ", round(-2.5), " ", round(2.4) // expect: 0.25 3 -3 2
print sign(-4), sign(0), sign(9) // expect: -101
print min(3, 1, 2), " ", max(3, 1, 2.5) // expect: 1 3
print limit(15, 0, 10), " ", limit(-1, 0, 10), " ", within(5, 1, 10), within(11, 1, 10) // expect: 10 0 10
print pi(), " ", pi(2) // expect: 3.14159265358979 6.28318530717959
print rtod(pi()), " ", dtor(180) // expect: 180 3.14159265358979
print polarR(3, 4), " ", rtod(polarA(0, 1)) // expect: 5 90
print round(cartX(2, pi())), " ", round(cartY(2, pi() / 2)) // expect: -2 2
// Near the largest number: dtor shrinks it (its result is finite), rtod's result is too large.
print dtor(1e308) // expect: 1.74532925199433e+306
