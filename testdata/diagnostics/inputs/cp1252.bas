// nontest: Windows-1252 text (diagnostics/input.t)
print "café € “"
prnt "été"
