-- appends10m: a string built from 10,000,000 pieces "x"; prints the length, 10000000.
-- Lua's strings are immutable, so s = s .. "x" copies s every time (about 30 s here); a
-- program that builds a long string in Lua collects the pieces in a table and joins them
-- once, as this one does.
local t = {}
for i = 1, 10000000 do
  t[#t + 1] = "x"
end
local s = table.concat(t)
print(#s)
