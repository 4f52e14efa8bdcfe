// Files a program reaches are confined to its own folder (rb run --allow-files DIR adds one).
print FileExists("files.bas")
// expect: 1
print FileExists("no_such_file.txt")
// expect: 0
DirSet "."
print FileExists("./files.bas")
// expect: 1
FileRename "no_such_file.txt", "other.txt" // expect-runtime-error: FileRename: cannot rename 'no_such_file.txt' to 'other.txt': No such file or directory
