// nontest: a UTF-8 byte-order mark (diagnostics/input.t)
print "café"
