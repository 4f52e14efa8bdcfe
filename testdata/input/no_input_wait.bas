// Without --keys or --events a headless run has no keyboard: waiting for a key is an error.
print "Press a key"
waitKey k // expect-runtime-error: waitKey: no scripted input to wait for (a headless run takes keys, clicks and dialog answers only from --keys or --events)
// expect: Press a key
