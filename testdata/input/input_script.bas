// With scripted input, `input` reads its lines from the script: an `input` step gives a whole
// line, typed keys make one up to enter. Standard input is not read.
// args: --events input_script.events
input "Name? ", name
print "Hello, ", name
input "Number? ", n
print n * 2
input more // expect-runtime-error: input: waiting for a line of input (input TEXT, or keys ending with {enter}), but the next scripted event is 'click 1 2 left' (input_script.events line 3)
// expect: Name? Bob Smith
// expect: Hello, Bob Smith
// expect: Number? 42
// expect: 84
