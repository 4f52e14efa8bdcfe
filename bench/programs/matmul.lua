-- matmul: C = A * B for 300 x 300 integer matrices held as tables of rows (Lua has no
-- two-dimensional arrays); prints the sum of C's elements, 546750000.
local n = 300
local a, b, c = {}, {}, {}
for i = 0, n - 1 do
  a[i], b[i], c[i] = {}, {}, {}
  for j = 0, n - 1 do
    a[i][j] = (i + 2 * j) % 10
    b[i][j] = (3 * i + j) % 10
    c[i][j] = 0
  end
end
for i = 0, n - 1 do
  for j = 0, n - 1 do
    local s = 0
    for k = 0, n - 1 do
      s = s + a[i][k] * b[k][j]
    end
    c[i][j] = s
  end
end
local total = 0
for i = 0, n - 1 do
  for j = 0, n - 1 do
    total = total + c[i][j]
  end
end
print(total)
