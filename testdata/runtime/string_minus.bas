print -"a" // expect-runtime-error: '-' needs a number, not a string
