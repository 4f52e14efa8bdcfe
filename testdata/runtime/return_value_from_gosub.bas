gosub G
end
sub S()
G:
  return 5 // expect-runtime-error: return with a value from a gosub (only subs return values)
