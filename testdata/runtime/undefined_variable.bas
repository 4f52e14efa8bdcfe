// Reading a variable that was never assigned stops the program, naming it.
x = 1
print x // expect: 1
y = x + z // expect-runtime-error: variable 'z' is used before it is given a value // expect-warning: variable 'z' is read but never assigned
