for i = 1 to 3
  i = "x"
next // expect-runtime-error: the for loop variable 'i' no longer holds a number
