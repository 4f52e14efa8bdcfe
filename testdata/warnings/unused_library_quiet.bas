// A library checked on its own (lib/RB-9.bas's idiom): its first jump is a goto over its own
// routines, which the programs that include it call. No label or sub it jumps over is reported
// as unused; a label after its end is.
goto LibraryEnd

Start: // called by an including program: no warning
  count = 0
return

sub Helper(a)
  print a
endsub

LibraryEnd:
print "library loaded" // expect: library loaded
end

Later: // expect-warning: label 'Later' is never used: no goto or gosub jumps to it, so the code after it never runs
  print "never"
return
