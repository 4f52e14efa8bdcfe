// stdin: only
input a
input b // expect-runtime-error: input: no more input to read (end of input)
