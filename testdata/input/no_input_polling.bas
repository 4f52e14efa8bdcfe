// Without scripted input, a program that polls the keyboard forever is stopped once it has
// polled for 60 s of virtual time (here 60 s / 11 ms passes).
rLocate 400, 300
while true
  getKey key // expect-runtime-error: getKey: no input (this headless run has no scripted input, and the program kept polling for 60 s of virtual time; give keys and clicks with --keys or --events)
  if key = ascii("q") then end
  delay 10
wend
