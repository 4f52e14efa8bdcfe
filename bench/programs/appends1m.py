# appends1m: s = s + "x", 1,000,000 times; prints the length, 1000000.
# Inside a function: CPython grows a string in place only in a local variable.
def main():
    s = ""
    for i in range(1000000):
        s = s + "x"
    print(len(s))


main()
