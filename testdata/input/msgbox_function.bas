// MsgBox is also a function: it returns the button that closed the box (1: OK). Its text may be
// an array of lines (a published program builds it with data and calls n = MsgBox(IM)).
// args: --events msgbox_function.events
data IM; "Bug Algorithm"
data IM; "Click OK to choose a map."
n = MsgBox(IM)
print n
// expect: 1
print MsgBox("Ready?", "Title") + 1
// expect: 2
MsgBox "the command form still works"
print "done"
// expect: done
