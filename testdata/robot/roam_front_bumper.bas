// The course labs' random roamer ("will roam randomly while avoiding objects"): drive while
// the front bumper is free, then turn 120 to 180 degrees. A front-bumper check always fires
// before a forward crash, so it never crashes: three seeds in an empty arena and three among
// drawn rectangles and circles, 150,000 steps each. (bench/robot/roamers.sh runs 1,000,000
// steps for 20 seeds.)
// args: --seed 1
for arena = 0 to 1
  for seed = 1 to 3
    clearScr
    if arena = 1
      rectangle 150, 120, 260, 200, black, black
      rectangle 520, 380, 640, 470, blue, blue
      rectangle 440, 40, 456, 250, black, black
      circle 300, 350, 380, 430, red, red
      circle 690, 300, 740, 350, black, black
    endif
    randomize seed
    rLocate 400, 300
    steps = 0
    turns = 0
    while steps < 150000
      while (rBumper() & 4) = 0 and steps < 150000
        rForward 1
        steps++
      wend
      rTurn 120 + random(60)
      turns++
    wend
    print arena, " ", seed, " ", turns > 100
  next
next
// expect: 0 1 1
// expect: 0 2 1
// expect: 0 3 1
// expect: 1 1 1
// expect: 1 2 1
// expect: 1 3 1
