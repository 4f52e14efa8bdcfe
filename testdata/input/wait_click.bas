// waitClick waits for a mouse button (at once when one is held); the button argument is optional.
// A click is down for one read of the mouse and up for the next.
// args: --events wait_click.events
waitClick x, y
print "click at ", x, ",", y
waitClick x, y, b
print "click at ", x, ",", y, " button ", b
readMouse x, y, b
print "pointer at ", x, ",", y, " button ", b
readMouse x, y
print "pointer at ", x, ",", y
// expect: click at 10,20
// expect: click at 30,40 button 6
// expect: pointer at 30,40 button 0
// expect: pointer at 50,60
