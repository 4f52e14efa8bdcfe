// args: --max-memory 400
// mFromString counts its fields, and the memory the array and its strings will take, before it
// makes any of them: 20,000,001 empty fields do not fit in 400 MiB (they took 1.6 GB before
// the limit stopped the run). The 20 MB text itself fits, also under AddressSanitizer.
s = replace(spaces(20000000), " ", ",")
mFromString a, s, "," // expect-runtime-error: out of memory: mFromString's 20000001 fields would need 1220 MiB, more than the 400 MiB of the --max-memory limit
