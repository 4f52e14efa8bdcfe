// Undefined and duplicate labels; labels are case-sensitive.
gosub drawSquare // expect-error: undefined label 'drawSquare'; did you mean 'DrawSquare'?
goto Nowhere // expect-error: undefined label 'Nowhere'
gosub Helper // expect-error: 'Helper' is a sub: use call Helper(...)
end
DrawSquare:
return
Twice:
return
Twice: // expect-error: duplicate label 'Twice'
return
sub Helper()
return
