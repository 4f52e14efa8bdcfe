// A NUL byte in a file name: the message quotes the whole name with the NUL escaped (as a C
// string, the name would end at it and the message with it).
print FileExists("../a" + char(0) + "b" + char(27) + ".bas") // expect-runtime-error: FileExists: '../a\x00b\x1b.bas' is outside the program's folder; rb lets a program reach only its own folder (rb run --allow-files DIR allows another)
