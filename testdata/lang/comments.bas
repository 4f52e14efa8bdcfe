// Every comment form: //, ', rem, /* */, after code too; none inside strings.
x = 1 // after code
' an apostrophe comment
rem a remark
REM upper-case remark
/* a block
   comment over lines */
print x /* inline */ + 1 // expect: 2
print "// not a comment" // expect: // not a comment
print "it's 'quoted'" // expect: it's 'quoted'
print "/* nor this */" // expect: /* nor this */
