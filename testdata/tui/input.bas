// Headless input on a terminal (tui_test.py input_terminal): what the user types shows once.
// stdin: 6
// stdin: robot
input "How many sides? ", n // expect: How many sides? 6
print "sides: " + n // expect: sides: 6
input "Name? ", s // expect: Name? robot
print "hello " + s // expect: hello robot
