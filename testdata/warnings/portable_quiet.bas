// rb check --portable is quiet on a program made only of what public RobotBASIC sources show:
// the seed's statements, the course's commands, sensors and loops, a published program's data
// and MaxDim, the SERVO program's subs, C-style operators and binary literals.
// check-args: --portable
data Names; "one", "two"
Main:
  rLocate 400, 300
  rInvisible Green
  LineWidth 4
  rPen Down
  for n = 1 to 4
    rForward 20
    rTurn 90
  next
  gosub Report
  call Add(2, total)
  print total
  if total == 5 && MaxDim(Names, 1) = 2
    print "ok"
  elseif total > 5
    print "more"
  else
    print "less"
  endif
  k = 0%101
  k++
  while k > 3
    k -= 3
  wend
  print k
end

Report:
  xyString 10, 10, "at ", rGPSX(), ",", rGPSY()
  print rBumper() & 4
return

sub Add(a, &sum)
  sum = a + 3
return
// expect: 0
// expect: 5
// expect: ok
// expect: 3
