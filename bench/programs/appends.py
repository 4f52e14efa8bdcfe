# appends: s = s + "x", 100,000 times; prints the length, 100000.
# Inside a function: CPython grows a string in place only in a local variable.
def main():
    s = ""
    for i in range(100000):
        s = s + "x"
    print(len(s))


main()
