print char(300) // expect-runtime-error: argument 1 (code) of char() must be a character code 0..255, got 300
