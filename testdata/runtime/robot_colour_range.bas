rLocate 400, 300
rInvisible -1 // expect-runtime-error: argument 1 (colour) of rInvisible must be a colour: 0..15 or an RGB() value
