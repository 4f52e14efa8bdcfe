// The clipboard belongs to the run: empty at the start, SetCBtext puts text on it.
print "[" + GetCBtext() + "]"
// expect: []
SetCBtext "route 66"
print GetCBtext()
// expect: route 66
SetCBtext 42
print GetCBtext() + "!"
// expect: 42!
