dim a[2]
if a = 1 then print 1 // expect-runtime-error: cannot compare an array
