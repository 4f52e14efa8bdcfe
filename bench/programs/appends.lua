-- appends: s = s .. "x", 150,000 times; prints the length, 150000.
local s = ""
for i = 1, 150000 do
  s = s .. "x"
end
print(#s)
