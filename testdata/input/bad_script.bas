// A malformed events file is a usage error (exit 64) that names the file and line; nothing runs.
// args: --events bad_script.events
// exit: 64
// expect-stderr: rb run: bad_script.events:3: unknown event 'jump' (expected key, hold, press, release, keys, mouse, click, button, edit, msgbox, input or wait)
print "not reached"
