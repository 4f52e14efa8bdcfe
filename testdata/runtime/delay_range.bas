// delay waits at most a day; a longer wait is a mistake, not a negative timer() afterwards.
delay 1e300 // expect-runtime-error: argument 1 (ms) of delay is out of range: 1e+300 (allowed: -86400000 to 86400000)
