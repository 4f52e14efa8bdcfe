// A built-in whose result is infinite stops the program at the call.
print pi(1e308) // expect-runtime-error: pi(): the result is too large
