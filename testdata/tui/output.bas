// The output pane: the tabs that ';' writes shown as spaces to the next 8-column stop, long
// lines wrapped, and a runtime error wrapped so that its hint is not cut off (tui_test.py).
total = 8
print "with " ; total ; " sides"
print "a line longer than the output pane is wide, so that it wraps onto the rows after it: END"
if total = 0 then totl = 0
print totl // expect-runtime-error: variable 'totl' is used before it is given a value; did you mean 'total'?
// expect: with 	8	 sides
// expect: a line longer than the output pane is wide, so that it wraps onto the rows after it: END
