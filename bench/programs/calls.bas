// calls: 40,000,000 gosub calls, each adds 1 to a counter; prints 40000000.
count = 0
for i = 1 to 40000000
  gosub Bump
next
print count
end

Bump:
  count = count + 1
return
