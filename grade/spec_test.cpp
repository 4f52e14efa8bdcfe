#include "spec.h"

#include <catch2/catch.hpp>

using namespace rb::grade;

TEST_CASE("comment expectations: output, errors, warnings, runtime errors", "[grade][spec]") {
  CommentSpec spec;
  parseComments(
      "print 1 // expect: 1\n"
      "print \"a  \" // expect: a  \n"
      "// expect:\n"
      "x = ) // expect-error: unexpected ')'\n"
      "y = z // expect-warning: 'z' is never assigned // expect-warning: second\n"
      "q = 1 / 0 // expect-runtime-error: division by zero\n"
      "// expect-stderr: random seed\n"
      "// expect-empty-line\n",
      "p.bas", true, spec);
  CHECK(spec.output == std::vector<std::string>{"1", "a  ", "", ""});
  CHECK(spec.errors == std::set<Expected>{{"p.bas", 4, "unexpected ')'"}});
  CHECK(spec.warnings == std::set<Expected>{{"p.bas", 5, "'z' is never assigned"}, {"p.bas", 5, "second"}});
  REQUIRE(spec.runtime);
  CHECK(*spec.runtime == Expected{"p.bas", 6, "division by zero"});
  CHECK(spec.stderrHas == std::vector<std::string>{"random seed"});
}

TEST_CASE("comment directives", "[grade][spec]") {
  CommentSpec spec;
  parseComments(
      "// nontest\n"
      "// args: --seed 7 --keys \"w a\"\n"
      "// check-args: --target rb9\n"
      "// stdin: 42\n"
      "// timeout: 2.5\n"
      "// exit: 64\n"
      "// skip: not yet\n"
      "// arguments: are not args\n",
      "p.bas", true, spec);
  CHECK(spec.nontest);
  CHECK(spec.args == std::vector<std::string>{"--seed", "7", "--keys", "w a"});
  CHECK(spec.checkArgs == std::vector<std::string>{"--target", "rb9"});
  CHECK(spec.stdinLines == std::vector<std::string>{"42"});
  CHECK(spec.timeout == 2.5);
  CHECK(spec.exit == 64);
  CHECK(spec.skip == "not yet");
  CHECK(spec.problems.empty());
}

TEST_CASE("comment problems and included files", "[grade][spec]") {
  CommentSpec spec;
  parseComments("// timeout: soon\n// exit: x\n// args: \"open\n", "p.bas", true, spec);
  CHECK(spec.problems.size() == 3);
  CHECK(spec.timeout == 30);

  // nontest counts only on line 1; an included file adds errors but no output or options.
  CommentSpec inc;
  std::vector<std::string> includes;
  parseComments("\n// nontest\n#include \"lib.bas\"\n", "main.bas", true, inc, &includes);
  CHECK_FALSE(inc.nontest);
  CHECK(includes == std::vector<std::string>{"lib.bas"});
  parseComments("print 1 // expect: 1\n// args: --seed 3\nx = ) // expect-error: bad\n", "lib.bas", false, inc);
  CHECK(inc.output.empty());
  CHECK(inc.args.empty());
  CHECK(inc.errors.size() == 1);
}

TEST_CASE("splitting words like a shell", "[grade][spec]") {
  CHECK(splitWords("a  b\tc") == std::vector<std::string>{"a", "b", "c"});
  CHECK(splitWords("--keys \"a b\" 'c d' e\\ f") == std::vector<std::string>{"--keys", "a b", "c d", "e f"});
  CHECK(splitWords("\"say \\\"hi\\\"\"") == std::vector<std::string>{"say \"hi\""});
  CHECK(splitWords("") == std::vector<std::string>{});
  CHECK_FALSE(splitWords("'open"));
}
