// args: --max-memory 100
// An array larger than the memory limit is refused before it is made.
dim a[60000000] // expect-runtime-error: out of memory: array 'a' would need 915 MiB, more than the 100 MiB of the --max-memory limit
