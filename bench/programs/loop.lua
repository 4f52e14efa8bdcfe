-- loop: 10,000,000 iterations of float arithmetic; prints 25000002500000.
local x = 0.0
for i = 1, 10000000 do
  x = x + i * 0.5
end
print(string.format("%.15g", x))
