-- appends: s = s .. "x", 100,000 times; prints the length, 100000.
local s = ""
for i = 1, 100000 do
  s = s .. "x"
end
print(#s)
