// Subs: parameters, then locals, then temporaries in the frame; &v is copied back after the
// call; _name is the main program's variable; arrays are global inside subs; code falling into
// a sub skips its body.
dim grid[3]
scale = 10
call Fill(2)
r = 0
call Twice(4, r)
print r; grid[2]; Area(3) // expect: 8	20	30
end

sub Fill(i)
  grid[i] = i * _scale
endsub

sub Twice(x, &v)
  v = x * 2
return

sub Area(w)
  h = w * 3
return w * h * 10 / 9
