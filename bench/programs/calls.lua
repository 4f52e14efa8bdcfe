-- calls: 40,000,000 calls of a local function, each adds 1 to a counter; prints 40000000.
local count = 0
local function bump()
  count = count + 1
end
for i = 1, 40000000 do
  bump()
end
print(count)
