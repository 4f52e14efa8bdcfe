// Unbounded recursion stops with a clear error instead of exhausting memory.
Recurse:
  gosub Recurse // expect-runtime-error: too many nested gosub/call (100000): runaway recursion?
return
