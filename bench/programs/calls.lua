-- calls: 1,000,000 calls of a local function, each adds 1 to a counter; prints 1000000.
local count = 0
local function bump()
  count = count + 1
end
for i = 1, 1000000 do
  bump()
end
print(count)
