// xyString's items make one string at most (64 MiB), as a line of print does.
s = spaces(40000000)
xyString 10, 10, s; s // expect-runtime-error: string too long (more than 67108864 characters)
