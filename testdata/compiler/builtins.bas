// Built-in calls: arguments in consecutive temporaries, output arguments written back after
// the call, a print-style command formats its items into one string, constants are numbers.
readMouse mx, my
xyString 10, 20, "at "; mx, my
v = max(mx, my, 3) + Red
print left("abcdef", v - 4); v // expect: abc	7
