// rb check --portable: statement forms rb accepts beyond what RobotBASIC's public sources show,
// each a warning where it is used (with a note where the sources show another way). The forms
// the sources show stay quiet: if/elseif/else/endif blocks, for/next, while/wend, labels,
// gosub, call, // comments, C-style operators; so do the forms the research notes recall from
// RobotBASIC's manual (step, continue, ' and rem and /* */ comments).
// check-args: --portable
n = 0
for i = 1 to 10 step 5
  n = n + i
next i  // expect-warning: a variable after next is rb's own: no public RobotBASIC source shows it
print n
// expect: 7
if n > 5 then  // expect-warning: 'then' at the end of a block if is rb's own: no public RobotBASIC source shows it
  print "big"
else if n > 2  // expect-warning: 'else if' is rb's own: no public RobotBASIC source shows it
  print "middle"
elseif n > 1 then  // expect-warning: 'then' after elseif is rb's own: no public RobotBASIC source shows it
  print "small"
end if  // expect-warning: 'end if' is rb's own: no public RobotBASIC source shows it
// expect: big
if n = 7 then print "seven" else print "other"  // expect-warning: 'else' in a single-line if is rb's own: no public RobotBASIC source shows it
// expect: seven
for k = 1 to 3
  if k = 2 then continue
  print k
next
// expect: 1
// expect: 3
print 7 mod 3  // expect-warning: the 'mod' operator is rb's own: no public RobotBASIC source shows it
// expect: 1
dim z  // expect-warning: dim of a name without brackets is rb's own: no public RobotBASIC source shows it
print z
// expect: 0
' an apostrophe comment
rem a remark
z = 1 /* a block comment */
Done: print "labelled"  // expect-warning: a statement on a label's line is rb's own: no public RobotBASIC source shows it
// expect: labelled
call Show(1)
Show(2)  // expect-warning: calling a sub without 'call' is rb's own: no public RobotBASIC source shows it
y = Twice(3)  // expect-warning: a sub's value in an expression is rb's own: no public RobotBASIC source shows it
print y
// expect: 1
// expect: 2
// expect: 6
end

sub Show(v)
  print v
end sub  // expect-warning: closing a sub with 'endsub' or 'end sub' is rb's own: no public RobotBASIC source shows it

sub Twice(v)
  return v * 2  // expect-warning: 'return' with a value is rb's own: no public RobotBASIC source shows it
endsub  // expect-warning: closing a sub with 'endsub' or 'end sub' is rb's own: no public RobotBASIC source shows it
