// Message boxes wait until they are answered: in a script with `msgbox ok`, or a key press of
// enter, esc or space (the box takes the key; the program does not see it).
// args: --events message_box.events
MsgBox "Ready?", "Robot"
print "first answered"
MsgBox "Still there?"
print "second answered"
getKey k
print "key after the boxes: ", k
MsgBox "One more" // expect-runtime-error: MsgBox: no more scripted input (the --events script is exhausted)
// expect: first answered
// expect: second answered
// expect: key after the boxes: 120
