// nontest: the warnings about a program's flow (diagnostics/check.t)
rForward 100
rLocate 400, 300
sides = 0
while sides < 4
  rForward 100
  rTurn 90
wend
gosub Inner
end

sub Draw(size)
Inner:
  print size
endsub

Spare:
  print "spare"
return
