-- callparams: 30 rounds of 1,000,000 calls of a local function with three parameters and two
-- locals (the total starts again at 0 each round); prints 1500007500000.
local function work(a, b, c)
  local x = a + b
  local y = x * c
  return y
end
local total
for r = 1, 30 do
  total = 0
  for i = 1, 1000000 do
    total = total + work(i, 2, 3)
  end
end
print(string.format("%.0f", total))
