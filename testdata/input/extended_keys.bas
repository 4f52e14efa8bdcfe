// Extended keys: getKey reads 0 for them, getKeyE and waitKey read codes above 255 (kc_Up, ...);
// keyDown(code) tests the key held now, letters with or without Shift. A tapped key is down for
// one read of the keyboard and up for the next.
// args: --events extended_keys.events
getKey k
print "getKey on up: ", k
getKeyE k
print "getKeyE on up: ", k, " = kc_Up: ", k = kc_Up
waitKey k
print "waitKey: ", k, " = kc_F1: ", k = kc_F1
waitKey k
print "esc: ", k = kc_Esc
getKey k
print "the next read sees the esc key up: ", k
print "keyDown a while A is held: ", keyDown(ascii("a"))
waitKey k
print "enter: ", k = kc_Enter, " ", kc_Enter
// expect: getKey on up: 0
// expect: getKeyE on up: 294 = kc_Up: 1
// expect: waitKey: 368 = kc_F1: 1
// expect: esc: 1
// expect: the next read sees the esc key up: 0
// expect: keyDown a while A is held: 1
// expect: enter: 1 13
