// A NUL byte in a file name: no file can have one, so the name is refused (a system call would
// see only the part before the NUL), and the message quotes the whole name with the NUL and the
// other control characters escaped.
print FileExists("../a" + char(0) + "b" + char(27) + ".bas") // expect-runtime-error: FileExists: '../a\x00b\x1b.bas' is not a file name (it holds a NUL character)
