gosub G // expect-warning: label 'G' is inside sub 'S': a gosub from outside the sub runs its code without the sub's variables; call the sub, or move the label out of it
end
sub S() // expect-warning: sub 'S' is never called
G:
  return 5 // expect-runtime-error: return with a value from a gosub (only subs return values)
