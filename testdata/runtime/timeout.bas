// args: --timeout 0.2
Loop:
  goto Loop // expect-runtime-error: stopped after 0.2 seconds (the --timeout limit)
