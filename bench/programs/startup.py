# startup: one line that prints 1: what starting the interpreter costs.
print(1)
