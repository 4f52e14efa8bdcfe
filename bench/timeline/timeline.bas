// The live view's timeline benchmark (bench/timeline/run.sh): 1,000,002 statements, every
// other one a setPixel, so that the screen changes all along the run and the recording keeps
// half a million keyframes besides the million steps.
for i = 0 to 499999
  setPixel i % 800, (i / 800) % 600, i % 16
next
print "done"
