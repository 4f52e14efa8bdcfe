setColor 20000000 // expect-runtime-error: argument 1 (colour) of setColor must be a colour: 0..15 or an RGB() value
