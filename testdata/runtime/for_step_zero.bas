for i = 1 to 10 step 0 // expect-runtime-error: for loop step is zero (the loop would never end)
next
