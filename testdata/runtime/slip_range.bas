rLocate 400, 300
rSlip 150 // expect-runtime-error: argument 1 (percent) of rSlip must be a percentage from 0 to 100
