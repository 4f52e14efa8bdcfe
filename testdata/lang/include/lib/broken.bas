// nontest: included by ../bad_include.bas
x = 1
pirnt x // expect-error: unknown command 'pirnt'; did you mean 'print'?
