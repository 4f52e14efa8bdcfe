for i = 1 to "ten" // expect-runtime-error: for loop bounds must be numbers
next
