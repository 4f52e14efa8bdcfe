// Unknown commands and functions get a "did you mean"; built-in names cannot be assigned.
prit "hello" // expect-error: unknown command 'prit'; did you mean 'print'?
delya 100 // expect-error: unknown command 'delya'; did you mean 'delay'?
frobnicate 1 // expect-error: unknown command 'frobnicate'
x = sqr(4) // expect-error: unknown function 'sqr'; did you mean 'sqrt'?
x = lenght("a") // expect-error: unknown function 'lenght'; did you mean 'length'?
abs(3) // expect-error: cannot use 'abs' as a statement: it is a built-in function; use its value, as in x = abs(...)
timer // expect-error: cannot use 'timer' as a statement: it is a built-in function; use its value, as in x = timer(...)
red // expect-error: cannot use 'red' as a statement: it is a built-in constant
red = 5 // expect-error: cannot assign to 'red': it is a built-in constant (Red: colour 4); use another name, such as 'myRed'
delay = 5 // expect-error: cannot assign to 'delay': it is a built-in command (delay ms: waits ms milliseconds); use another name, such as 'myDelay'
abs = 1 // expect-error: cannot assign to 'abs': it is a built-in function (abs(x): absolute value); use another name, such as 'myAbs'
x = pi // expect-error: cannot use 'pi' as a variable: it is a built-in function; write pi()
x = delay // expect-error: cannot use 'delay' as a variable: it is a built-in command
x = delay(5) // expect-error: cannot call 'delay' as a function: it is a built-in command; write it as a statement
x = abs[1] // expect-error: cannot use 'abs' as an array: it is a built-in function (abs(x): absolute value); use another name, such as 'myAbs'
dim red[3] // expect-error: cannot use 'red' as an array: it is a built-in constant (Red: colour 4); use another name, such as 'myRed'
Nosuch(1) // expect-error: unknown command or sub 'Nosuch'
input "speed? ", rForward // expect-error: cannot assign to 'rForward': it is a built-in command (rForward distance: moves the robot forward (negative: backward), pixel by pixel); use another name, such as 'myRForward'
call delay(5) // expect-error: cannot use 'delay' as a sub name: it is a built-in command (delay ms: waits ms milliseconds)
red[2] = 1 // expect-error: cannot use 'red' as an array: it is a built-in constant (Red: colour 4); use another name, such as 'myRed'
x = Red(2) // expect-error: cannot call 'Red' as a function: it is a built-in constant
