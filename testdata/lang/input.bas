// input: a prompt, then a number when the line is a number, else a string.
// stdin: 42
// stdin: hello world
// stdin: 3.5
input "Number? ", n
input s
input "x"; x
print n + 1 // expect: Number? x43
print s // expect: hello world
print x * 2 // expect: 7
