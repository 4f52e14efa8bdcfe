-- strings: 900,000 iterations of concatenation with numbers, case change, substrings,
-- search and length; prints 29477790.
local total = 0
for i = 1, 900000 do
  local s = "item" .. i .. "-" .. (i % 7)
  local u = string.upper(s)
  local t = string.sub(u, 1, 3) .. string.sub(s, 5, 7) .. string.lower(string.sub(u, -4))
  total = total + #t + #s + string.find(u, "-", 1, true)
end
print(total)
