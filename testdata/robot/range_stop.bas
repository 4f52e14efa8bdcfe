// The labs' snippet: drive until the range sensor reads 20 pixels or less.
rLocate 400, 300
while rRange() > 20
   rForward 1
wend
y = rGPSY()
print y >= 38 and y <= 42 // expect: 1
