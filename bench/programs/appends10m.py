# appends10m: s = s + "x", 10,000,000 times; prints the length, 10000000.
# Inside a function: CPython grows a string in place only in a local variable.
def main():
    s = ""
    for i in range(10000000):
        s = s + "x"
    print(len(s))


main()
