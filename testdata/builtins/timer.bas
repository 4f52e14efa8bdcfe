// timer() and delay run on a virtual clock in headless runs: no real waiting, and a loop
// waiting for the clock ends.
t = timer()
delay 5000
print timer() - t >= 5000 // expect: 1
start = timer()
while timer() < start + 100
wend
print "waited" // expect: waited
