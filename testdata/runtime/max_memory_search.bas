// args: --max-memory 100
// The search for a long string (instr, contains, replace, extract, mFromString) counts its
// table, 4 bytes a character of the string looked for, against --max-memory before making it.
s = spaces(30000000)
print instr(s, s) // expect-runtime-error: out of memory: searching for a string of 30000000 characters would need 114 MiB, more than the 100 MiB of the --max-memory limit
