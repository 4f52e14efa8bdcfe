s = spaces(100000000) // expect-runtime-error: spaces(): string too long
