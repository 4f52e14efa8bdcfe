// nontest: lines whose columns differ by unit: tabs, accents, CJK text and an emoji before the errors.
	foo 1
s = "😀é" + zork(x)
t$ = "中文字" : rForwrd 10
	u = "é" + 	bad(1)
