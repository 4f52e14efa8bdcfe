// nontest: warnings before a run (diagnostics/run.t)
if 1
  print "in the if"
