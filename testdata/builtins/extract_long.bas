// args: --timeout 5
// extract with a delimiter of 64 characters and more searches it in linear time, as instr does,
// however the strings repeat: a 500,000-letter delimiter over 4,000,000 times one letter took
// minutes when it was compared at every position.
h = replace(spaces(4000000), " ", "a")
d = left(h, 499999) + "b"
print length(extract(h, d, 1)) // expect: 4000000
print extract(h, d, 2) = "" // expect: 1
print extract(h + d + "x" + d + "y", d, 3) // expect: y
print "done" // expect: done
