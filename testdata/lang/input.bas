// input: a prompt, then a number when the line is a number, else a string. Headless, the line
// read is written after the prompt and ends the line, as RobotBASIC's screen shows it.
// stdin: 42
// stdin: hello world
// stdin: 3.5
input "Number? ", n // expect: Number? 42
input s // expect: hello world
input "x"; x // expect: x3.5
print n + 1 // expect: 43
print s // expect: hello world
print x * 2 // expect: 7
