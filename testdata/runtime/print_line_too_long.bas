// A line of print is one string at most (64 MiB): items of a long string cannot join into more
// (print s; s; s ... of a 60 MB string took 12 GB and ran past the time limit).
s = spaces(40000000)
print s; s // expect-runtime-error: string too long (more than 67108864 characters)
