// goto and gosub jump to labels; every control transfer reports the statements counted since
// the previous one (steps), which is how --max-steps counts without an instruction per line.
gosub Show
goto Done
print "skipped"
Show:
  print "show"
  return
Done:
print "done"
// expect: show
// expect: done
