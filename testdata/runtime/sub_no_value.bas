x = F() // expect-runtime-error: sub 'F' returned no value (use return with a value)
end
sub F()
return
