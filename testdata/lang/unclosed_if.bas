// An if ... else left without endif runs (a published program relies on it); rb check warns.
x = 1
gosub Check
x = 0
gosub Check
end

Check:
  if x = 1 // expect-warning: if without endif before the end of the file; the block runs to that point
    print "one" // expect: one
    return
  else
    print "zero" // expect: zero
    return
