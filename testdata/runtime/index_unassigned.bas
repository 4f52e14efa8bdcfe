dim a[3]
print a[k] // expect-runtime-error: variable 'k' is used before it is given a value // expect-warning: variable 'k' is read but never assigned
