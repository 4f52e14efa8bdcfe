// A "did you mean" comes only from names that can stand where the word stands.
// At the start of a statement: commands and the keywords that start statements, never an
// operator (`not`) or a word from inside a statement (`to`).
nxt // expect-error: unknown command 'nxt'; did you mean 'next'?
nto 1 // expect-error: unknown command 'nto'
wnd // expect-error: unknown command 'wnd'; did you mean 'wend'?
rForwrd 10 // expect-error: unknown command 'rForwrd'; did you mean 'rForward'?
// A call as a statement: subs and commands (a function's value must be used, as below).
lenght("abc") // expect-error: unknown command or sub 'lenght'
// In an expression: functions (and subs) where a call stands; variables and constants where a
// value stands, first the constants that fit the argument (rPen takes Up or Down, setColor a
// colour, flip On or Off).
count = 1
total = count + cuont // expect-warning: variable 'cuont' is read but never assigned; did you mean 'count'?
rPen dwn // expect-warning: variable 'dwn' is read but never assigned; did you mean 'Down'?
setColor gren // expect-warning: variable 'gren' is read but never assigned; did you mean 'Green'?
rLocate 10, 10, 0, 20, Yelow // expect-warning: variable 'Yelow' is read but never assigned; did you mean 'Yellow'?
flip onn // expect-warning: variable 'onn' is read but never assigned; did you mean 'On'?
done = tru // expect-warning: variable 'tru' is read but never assigned; did you mean 'True'?
print lenght("abc") // expect-error: unknown function 'lenght'; did you mean 'length'?
// After goto and gosub: labels.
goto Strat // expect-error: undefined label 'Strat'; did you mean 'Start'?
Start:
// A built-in's name for a variable: which built-in it is, and a name the program does not use.
length = 100 // expect-error: cannot assign to 'length': it is a built-in function (length(s): number of characters); use another name, such as 'myLength'
for Red = 1 to 2 // expect-error: cannot assign to 'Red': it is a built-in constant (Red: colour 4); use another name, such as 'myRed'
next
