// A script whose next event the program never reads: the click waits for a read of the mouse,
// while the program polls only the keyboard. The run stops with an error that names the event.
// args: --events stuck_script.events
repeat
  getKey k // expect-runtime-error: getKey: the --events script is stuck at 'click 3 4 left' (stuck_script.events line 2): the program kept polling for 60 s of virtual time without reading the mouse (it read the keyboard)
  if k <> 0 then print "key ", k
until k = ascii("q")
// expect: key 97
