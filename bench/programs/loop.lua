-- loop: 8 rounds of 10,000,000 iterations of float arithmetic (x starts again at 0 each
-- round); prints 25000002500000.
local x
for r = 1, 8 do
  x = 0.0
  for i = 1, 10000000 do
    x = x + i * 0.5
  end
end
print(string.format("%.15g", x))
