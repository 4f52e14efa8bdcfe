-- appends1m: a string built from 1,000,000 pieces "x"; prints the length, 1000000.
-- Lua's strings are immutable, so s = s .. "x" copies s every time (about 30 s here); a
-- program that builds a long string in Lua collects the pieces in a table and joins them
-- once, as this one does.
local t = {}
for i = 1, 1000000 do
  t[#t + 1] = "x"
end
local s = table.concat(t)
print(#s)
