#include <catch2/catch.hpp>

#include "lang/builtins.h"
#include "lang/lexer.h"
#include "lang/parser.h"

using namespace rb;
using ast::ExprKind;
using ast::StmtKind;

namespace {
/// The built-ins these tests parse against: the parser needs only to know the commands.
const BuiltinTable& testBuiltins() {
  static const BuiltinTable table({
      {"randomize", BuiltinKind::Command, "math", "seed", nullptr, 0, "restarts the random numbers"},
      {"xyText", BuiltinKind::Command, "graphics", "x, y, items...", nullptr, 0, "text at x, y"},
      {"mid", BuiltinKind::Function, "string", "s, start [, count]", nullptr, 0, "part of s"},
      {"Red", BuiltinKind::Constant, "colour", "", nullptr, 4, "colour 4"},
  });
  return table;
}

struct Parsed {
  SourceSet sources;
  ast::Arena arena;
  DiagnosticList diags;
  std::vector<ast::Stmt*> stmts;
};
std::unique_ptr<Parsed> parse(const std::string& text) {
  auto p = std::make_unique<Parsed>();
  uint32_t f = p->sources.add("t.bas", text);
  auto toks = lex(p->sources, f, p->diags);
  p->stmts = parseTokens(toks, p->arena, testBuiltins(), p->diags);
  return p;
}
/// A compact rendering of an expression tree: (op a b).
std::string show(const ast::Expr* e) {
  std::string out;
  switch (e->kind) {
    case ExprKind::Int: return std::to_string(e->ival);
    case ExprKind::Var: return std::string(e->text);
    case ExprKind::Unary:
    case ExprKind::Binary:
      out += '(';
      out += tokName(e->op);
      for (const ast::Expr* a : e->args) {
        out += ' ';
        out += show(a);
      }
      out += ')';
      return out;
    default: return "?";
  }
}
std::string exprOf(const std::string& text) {
  auto p = parse("x = " + text);
  REQUIRE_FALSE(p->diags.hasErrors());
  return show(p->stmts[0]->value);
}
}  // namespace

TEST_CASE("precedence follows the documented table", "[parser]") {
  CHECK(exprOf("1 + 2 * 3") == "('+' 1 ('*' 2 3))");
  CHECK(exprOf("2 ^ 3 ^ 2") == "('^' 2 ('^' 3 2))");
  CHECK(exprOf("-a ^ 2") == "('^' ('-' a) 2)");
  CHECK(exprOf("a & 3 = 0") == "('=' ('&' a 3) 0)");
  CHECK(exprOf("a | b & c") == "('|' a ('&' b c))");
  CHECK(exprOf("a or b and c") == "('or' a ('and' b c))");
  CHECK(exprOf("not a = b") == "('=' ('not' a) b)");
  CHECK(exprOf("a << 1 + 1") == "('<<' a ('+' 1 1))");
  CHECK(exprOf("a < b = c") == "('=' ('<' a b) c)");
}

TEST_CASE("statements of a line: labels, single-line if with else", "[parser]") {
  auto p = parse("Main: print 1\nif a then b = 1 else gosub X\n");
  REQUIRE_FALSE(p->diags.hasErrors());
  REQUIRE(p->stmts.size() == 3);
  CHECK(p->stmts[0]->kind == StmtKind::Label);
  CHECK(p->stmts[1]->kind == StmtKind::Print);
  CHECK(p->stmts[2]->kind == StmtKind::IfLine);
  REQUIRE(p->stmts[2]->body.size() == 2);
  CHECK(p->stmts[2]->body[1]->kind == StmtKind::Gosub);
}

TEST_CASE("block if forms", "[parser]") {
  auto p = parse("if a\nelseif b then\nelse if c\nelse\nend if\nendif");
  REQUIRE_FALSE(p->diags.hasErrors());
  std::vector<StmtKind> k;
  for (auto* s : p->stmts) k.push_back(s->kind);
  CHECK(k == std::vector<StmtKind>{StmtKind::If, StmtKind::ElseIf, StmtKind::ElseIf, StmtKind::Else,
                                   StmtKind::EndIf, StmtKind::EndIf});
}

TEST_CASE("print(x) is print with a parenthesised expression", "[parser]") {
  auto p = parse("print(1) + 2");
  REQUIRE_FALSE(p->diags.hasErrors());
  CHECK(show(p->stmts[0]->exprs[0]) == "('+' 1 2)");
}

TEST_CASE("a command may take its arguments in parentheses", "[parser]") {
  auto p = parse("randomize(5)\nmid = 1");
  CHECK(p->stmts[0]->kind == StmtKind::Command);
  CHECK(p->stmts[0]->exprs.size() == 1);
  // An assignment to a built-in's name parses; the compiler rejects it (BuiltinTable::misuse).
  CHECK(p->stmts[1]->kind == StmtKind::Assign);
  CHECK_FALSE(p->diags.hasErrors());
}

TEST_CASE("a built-in that is no command cannot start a statement", "[parser]") {
  auto p = parse("mid(1, 2)\nRED\n");
  REQUIRE(p->diags.errorCount() == 2);
  CHECK(p->diags.all()[0].message ==
        "cannot use 'mid' as a statement: it is a built-in function; use its value, as in x = mid(...)");
  CHECK(p->diags.all()[1].message == "cannot use 'RED' as a statement: it is a built-in constant");
}

TEST_CASE("one error per bad line, parsing goes on", "[parser]") {
  auto p = parse("x = (1\nprint 1\ny = ]\n");
  CHECK(p->diags.errorCount() == 2);
  CHECK(p->stmts.size() == 1);
}

TEST_CASE("a misspelt closer is kept as a broken closer that names the word", "[parser]") {
  auto p = parse("nxt\nL: wnd\nif 1 then nxt\nendf 5\nprnt 1\n");
  REQUIRE(p->diags.errorCount() == 5);
  CHECK(p->diags.all()[0].message == "unknown command 'nxt'; did you mean 'next'?");
  // nxt, the label and wnd, endf: the single-line if's nxt and prnt leave nothing.
  REQUIRE(p->stmts.size() == 4);
  CHECK(p->stmts[0]->kind == StmtKind::Next);
  CHECK(p->stmts[0]->broken);
  CHECK(p->stmts[0]->name == "nxt");
  CHECK(p->stmts[1]->kind == StmtKind::Label);
  CHECK(p->stmts[2]->kind == StmtKind::Wend);
  CHECK(p->stmts[2]->name == "wnd");
  CHECK(p->stmts[3]->kind == StmtKind::EndIf);
  CHECK(p->stmts[3]->broken);
}

TEST_CASE("deep nesting is an error, not a crash", "[parser]") {
  auto p = parse("x = " + std::string(5000, '(') + "1" + std::string(5000, ')'));
  REQUIRE(p->diags.errorCount() == 1);
  CHECK(p->diags.all()[0].message == "expression nested too deeply");
  auto q = parse("x = " + std::string(5000, '-') + "1");
  CHECK(q->diags.errorCount() == 1);
}

TEST_CASE("one expression alone, as a watch is written", "[parser]") {
  auto expr = [](const std::string& text, std::string* error = nullptr) -> std::string {
    SourceSet sources;
    ast::Arena arena;
    DiagnosticList diags;
    uint32_t f = sources.add("watch", text);
    ast::Expr* e = parseExpression(sources, f, arena, testBuiltins(), diags);
    if (error && !diags.all().empty()) *error = diags.all()[0].message;
    return e ? show(e) : "";
  };
  CHECK(expr("x * 2 + 1") == "('+' ('*' x 2) 1)");
  CHECK(expr("a[3] + 1") != "");
  CHECK(expr("mid(s, 2)") != "");
  CHECK(expr("n = 3") != "");  // '=' in an expression compares
  std::string error;
  CHECK(expr("", &error).empty());
  CHECK(error == "expected an expression, found end of line");
  CHECK(expr("x 2", &error).empty());
  CHECK(error == "unexpected '2' after the end of the expression");
  CHECK(expr("(x + ", &error).empty());
  CHECK_FALSE(error.empty());
}

TEST_CASE("two values side by side: the missing operator, where, and a fix-it inserting it", "[parser]") {
  struct Case {
    std::string line;
    std::string message;
    uint32_t col, endCol;  // the second value's range
    uint32_t fixCol;       // where the fix-it inserts
    std::string insert;
  };
  const Case cases[] = {
      {"print \"in \" + n \" moves\"", "missing '+' between 'n' and \" moves\"", 17, 24, 16, " +"},
      {"x = \"x = \"n", "missing '+' between \"x = \" and 'n'", 11, 11, 11, " + "},
      {"x = 2 n", "missing '*' between '2' and 'n'", 7, 7, 6, " *"},
      {"x = 2n", "missing '*' between '2' and 'n'", 6, 6, 6, " * "},
      {"x = (a + b) c", "missing '*' between '(a + b)' and 'c'", 13, 13, 12, " *"},
      {"x = 2 (a + b)", "missing '*' between '2' and '(a + b)'", 7, 13, 6, " *"},
      {"x = mid(s, 1) \"!\"", "missing '+' between 'mid(s, 1)' and \"!\"", 15, 17, 14, " +"},
      {"x = a b", "missing '+' between 'a' and 'b'", 7, 7, 6, " +"},
      {"print a b", "missing ',' between 'a' and 'b'", 9, 9, 8, ","},
      {"print a[1]b", "missing ',' between 'a[1]' and 'b'", 11, 11, 11, ", "},
      {"xyText 1 2, \"s\"", "missing ',' between '1' and '2'", 10, 10, 9, ","},
      {"if a then return \"a\" b", "missing '+' between \"a\" and 'b'", 22, 22, 21, " +"},
  };
  for (const Case& c : cases) {
    INFO(c.line);
    auto p = parse(c.line + "\n");
    REQUIRE(p->diags.errorCount() == 1);
    const Diagnostic& d = p->diags.all()[0];
    CHECK(d.message == c.message);
    CHECK(d.code == "rb-missing-operator");
    CHECK(d.loc.line == 1);
    CHECK(d.loc.col == c.col);
    CHECK(d.end.col == c.endCol);
    REQUIRE(d.fixits.size() == 1);
    CHECK(d.fixits[0].start.col == c.fixCol);
    CHECK(d.fixits[0].end == d.fixits[0].start);
    CHECK(d.fixits[0].replacement == c.insert);
  }
}

TEST_CASE("where the grammar goes on, values side by side are no missing operator", "[parser]") {
  for (const char* line : {"print a; b, c", "print(1) + 2", "if a then b = 1 else b = 2", "for i = 1 to 9 step 2",
                           "x = a -1", "x = f (1)", "x = a [1]", "a [1] = 2", "randomize 5", "randomize(5)",
                           "L: print 1", "x = a mod b and not c", "if a then return else print 1"}) {
    INFO(line);
    auto p = parse(std::string(line) + "\n");
    CHECK_FALSE(p->diags.hasErrors());
  }
  // A command's arguments (a comma may be missing, or the arguments too many), a command after
  // a value (two statements on one line), a word before 'then': the grammar's own messages.
  auto message = [](const std::string& line) {
    auto p = parse(line + "\n");
    REQUIRE(p->diags.errorCount() == 1);
    CHECK(p->diags.all()[0].code == "rb-syntax");
    return p->diags.all()[0].message;
  };
  CHECK(message("randomize 1 2") == "unexpected '2' after the end of the statement");
  CHECK(message("x = 1 randomize 5") == "unexpected 'randomize' after the end of the statement");
  CHECK(message("if a b then c = 1") == "expected 'then' or the end of the line after the if condition, found 'b'");
  CHECK(message("for i = 1 9") == "expected 'to', found a number");
  CHECK(message("x = (a b)") == "expected ')', found 'b'");
}
