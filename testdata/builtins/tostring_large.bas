// toString with decimals shows every digit of a large number (301 digits, the point, 15 decimals).
print length(toString(1e300, 15)) // expect: 317
