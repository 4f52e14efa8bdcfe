print ln(0) // expect-runtime-error: ln(): the logarithm is only defined for numbers above 0
