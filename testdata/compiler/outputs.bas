// Finishing the code: a by-reference parameter the sub sets on every path before reading it
// or returning is an output, and calls do not copy it in (Split's &whole and &part; Bump reads
// its &n first, and Clip sets &v on one path only, so theirs are copied in). A jump to a
// return becomes the return (the end of Split's first branch).
total = 5
call Split(7, w, p)
call Bump(total)
v = 1
call Clip(-3, v)
print w; p; total; v // expect: 3	1	6	1
end

sub Split(x, &whole, &part)
  if x < 4
    whole = 0
    part = x
  else
    part = x % 2
    whole = (x - part) / 2
  endif
return

sub Bump(&n)
  n = n + 1
return

sub Clip(x, &v)
  if x > 0 then v = x
return
