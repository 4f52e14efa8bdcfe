// A name outside the program's folder is refused, also through .. and DirSet.
print FileExists("files.bas")
// expect: 1
print FileExists("../README.md") // expect-runtime-error: FileExists: '../README.md' is outside the program's folder; rb lets a program reach only its own folder (rb run --allow-files DIR allows another)
