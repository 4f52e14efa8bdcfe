print 1
/* this comment never ends // expect-error: unterminated /* comment
print 2
