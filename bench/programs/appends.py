# appends: s = s + "x", 150,000 times; prints the length, 150000.
# Inside a function: CPython grows a string in place only in a local variable.
def main():
    s = ""
    for i in range(150000):
        s = s + "x"
    print(len(s))


main()
