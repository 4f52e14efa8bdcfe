// --allow-files DIR lets a program reach another folder too.
// args: --allow-files ..
print FileExists("../README.md")
// expect: 1
DirSet ".."
print FileExists("README.md")
// expect: 1
