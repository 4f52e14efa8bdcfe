// A program that waits for a key when the scripted keys are used up stops with an error.
// args: --keys "ab"
waitKey k
waitKey k
print "two keys read"
waitKey k // expect-runtime-error: waitKey: no more scripted input (the --keys text is exhausted)
// expect: two keys read
