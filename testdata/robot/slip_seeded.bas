// rSlip draws its error from the run's seeded generator: the same seed, the same path.
// args: --seed 11
rLocate 400, 300
rSlip 15
for n = 1 to 4
  rForward 120
  rTurn 90
next
print rGPSX(), ",", rGPSY(), " ", rCompass() // expect: 417,308 356
