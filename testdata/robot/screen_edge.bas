// The screen edge is a black wall: rLook reads 0 there, and driving into it crashes.
rLocate 400, 300
print rLook(), " ", rRange() // expect: 0 281
rForward 279
print rGPSY() // expect: 21
rForward 5 // expect-runtime-error: robot crashed into an obstacle: the edge of the screen
