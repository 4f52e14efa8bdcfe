// A program includes only files in its own folder tree and the library folders (or folders the
// person running rb allows with --allow-files): nothing of a refused file is read.
#include "/etc/passwd" // expect-error: cannot #include '/etc/passwd': it is outside the program's folder and the library folders (rb run --allow-files DIR allows another folder)
#include "../input.bas" // expect-error: cannot #include '../input.bas': it is outside the program's folder and the library folders (rb run --allow-files DIR allows another folder)
#include "lib/helpers.bas"
print "never runs"
