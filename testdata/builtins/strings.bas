// String built-ins; positions are 1-based.
s = "Hello World"
print length(s) // expect: 11
print left(s, 5), "|", right(s, 5), "|", mid(s, 7, 3), "|", mid(s, 7) // expect: Hello|World|Wor|World
print left(s, 0), "|", left(s, 99), "|", mid(s, 20) // expect: |Hello World|
print upper(s), " ", lower(s) // expect: HELLO WORLD hello world
print "[", trim("  a b  "), "][", trimL("  a "), "][", trimR(" a  "), "]" // expect: [a b][a ][ a]
print "[", spaces(3), "]", reverse("abc") // expect: [   ]cba
print instr(s, "o"), " ", instr(s, "o", 6), " ", instr(s, "z") // expect: 5 8 0
print contains(s, "World"), contains(s, "world") // expect: 10
print replace("a-b-c", "-", "+") // expect: a+b+c
print extract("x,y,z", ",", 2), extract("x,y,z", ",", 4), "." // expect: y.
print char(65), ascii("A"), ascii("") // expect: A650
print toString(3.14159, 2), " ", toString(7) + "!" // expect: 3.14 7!
print toNumber("42") + 1, " ", toNumber(" 2.5 ") * 2 // expect: 43 5
print isNumber(5), isNumber("5"), isString("5") // expect: 101
print ascii("q") // expect: 113
