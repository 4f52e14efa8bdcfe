// Unknown commands and functions get a "did you mean"; built-in names cannot be assigned.
prit "hello" // expect-error: unknown command 'prit'; did you mean 'print'?
delya 100 // expect-error: unknown command 'delya'; did you mean 'delay'?
frobnicate 1 // expect-error: unknown command 'frobnicate'
x = sqr(4) // expect-error: unknown function 'sqr'; did you mean 'sqrt'?
x = lenght("a") // expect-error: unknown function 'lenght'; did you mean 'length'?
abs(3) // expect-error: 'abs' is a function: use its value, as in x = abs(...)
timer // expect-error: 'timer' is a function: use its value, as in x = timer(...)
red // expect-error: 'red' is a constant, not a command
red = 5 // expect-error: cannot assign to 'red': it is a built-in constant
delay = 5 // expect-error: cannot assign to 'delay': it is a command
abs = 1 // expect-error: cannot assign to 'abs': it is a built-in function
x = pi // expect-error: 'pi' is a function: write pi()
x = delay // expect-error: 'delay' is a command and has no value
x = delay(5) // expect-error: 'delay' is a command, not a function: write it as a statement
x = abs[1] // expect-error: 'abs' is a built-in name, not an array
dim red[3] // expect-error: cannot dim 'red': it is a built-in name
Nosuch(1) // expect-error: unknown command or sub 'Nosuch'
