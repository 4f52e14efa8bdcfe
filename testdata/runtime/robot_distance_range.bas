// Robot distances are bounded (a million pixels): a huge one is an error, never a cast that overflows.
rLocate 400, 300
rForward 1e18 // expect-runtime-error: argument 1 (distance) of rForward is out of range: 1e+18 (allowed: -1000000 to 1000000)
