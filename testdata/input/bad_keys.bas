// A malformed --keys text is a usage error too.
// args: --keys "ab{up"
// exit: 64
// expect-stderr: rb run: --keys: missing } after '{up'
print "not reached"
