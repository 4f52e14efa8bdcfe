// stdin: only
input a // expect: only
input b // expect-runtime-error: input: no more input to read (end of input)
