#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "lang/checker.h"
#include "program_loader.h"

using namespace rb;
using namespace rb::run;

namespace {

/// Every diagnostic of a loaded file, formatted, one after another.
std::string allDiagnostics(const LoadedFile& f) {
  std::string out;
  for (const Diagnostic& d : f.diags.all()) out += formatDiagnostic(f.program->sources, d);
  return out;
}

/// The golden programs and diagnostics inputs: programs with every kind of statement and error.
std::vector<std::string> testPrograms() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(RB_TESTDATA_DIR))
    if (e.is_regular_file() && e.path().extension() == ".bas") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("rb check finds the same diagnostics without keeping the compiled code or the trees", "[check]") {
  std::vector<std::string> files = testPrograms();
  REQUIRE(files.size() > 100);
  for (const std::string& file : files) {
    INFO(file);
    // The reference: the trees, compiled, then linted in a walk of its own.
    LoadedFile kept = loadFile(file, CompileOptions{}, false);
    if (kept.program) {
      lintProgram(*kept.program, kept.diags);
      kept.diags.sort();
    }
    CompileOptions dropped;
    dropped.keepCode = false;
    LoadedFile checked = loadFile(file, dropped, true);
    LoadedFile compact = loadFile(file, dropped, true, true);
    REQUIRE(kept.program);
    REQUIRE(checked.program);
    CHECK(allDiagnostics(checked) == allDiagnostics(kept));
    REQUIRE(compact.program);
    CHECK(compact.program->stmts.empty());
    CHECK(allDiagnostics(compact) == allDiagnostics(kept));
    CHECK(bool(checked.compiled) == bool(kept.compiled));
    if (checked.compiled) CHECK(checked.compiled->code.empty());
  }
}

namespace {

bool sameExpr(const ast::Expr* a, const ast::Expr* b) {
  if (!a || !b) return a == b;
  if (a->kind != b->kind || a->op != b->op || !(a->loc == b->loc) || !(a->end == b->end) ||
      a->text.data() != b->text.data() || a->text.size() != b->text.size() ||
      a->args.size() != b->args.size())
    return false;
  if (a->kind == ast::ExprKind::Float ? a->dval != b->dval : a->ival != b->ival) return false;
  for (size_t i = 0; i < a->args.size(); ++i)
    if (!sameExpr(a->args[i], b->args[i])) return false;
  return true;
}

bool sameStmt(const ast::Stmt* a, const ast::Stmt* b) {
  if (a->kind != b->kind || a->op != b->op || !(a->loc == b->loc) || !(a->nameLoc == b->nameLoc) ||
      a->name.data() != b->name.data() || a->name.size() != b->name.size() ||
      a->paren != b->paren || a->broken != b->broken || a->seps != b->seps ||
      !sameExpr(a->target, b->target) || !sameExpr(a->value, b->value) ||
      a->exprs.size() != b->exprs.size() || a->params.size() != b->params.size() ||
      a->body.size() != b->body.size())
    return false;
  for (size_t i = 0; i < a->exprs.size(); ++i)
    if (!sameExpr(a->exprs[i], b->exprs[i])) return false;
  for (size_t i = 0; i < a->params.size(); ++i) {
    const ast::Param &p = a->params[i], &q = b->params[i];
    if (p.name.data() != q.name.data() || p.name.size() != q.name.size() || !(p.loc == q.loc) ||
        p.byRef != q.byRef)
      return false;
  }
  for (size_t i = 0; i < a->body.size(); ++i)
    if (!sameStmt(a->body[i], b->body[i])) return false;
  return true;
}

}  // namespace

TEST_CASE("statements read back from the compact form equal the parsed ones", "[check]") {
  for (const std::string& file : testPrograms()) {
    INFO(file);
    LoadedFile trees = loadFile(file, CompileOptions{}, false);
    REQUIRE(trees.program);
    const std::vector<ast::Stmt*>& stmts = trees.program->stmts;
    ast::CompactStmts store(trees.program->sources);
    for (const ast::Stmt* s : stmts) store.add(*s);
    REQUIRE(store.size() == stmts.size());
    ast::Arena scratch;
    // Twice: the second time every node comes from a reused block and must be wholly rewritten.
    for (int round = 0; round < 2; ++round) {
      ast::StmtCursor c(store, scratch);
      for (const ast::Stmt* want : stmts) {
        scratch.reset();
        CHECK(sameStmt(c.next(), want));
      }
      CHECK(c.done());
    }
  }
  // The compact load keeps every statement too.
  LoadedFile compact = loadFile(testPrograms().front(), CompileOptions{}, false, true);
  LoadedFile trees = loadFile(testPrograms().front(), CompileOptions{}, false);
  CHECK(compact.program->stmtCount() == trees.program->stmts.size());
}

namespace {

/// Writes `text` to a file of its own in the temporary folder and returns its path.
std::string writeProgram(const std::string& name, const std::string& text) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "rb_program_loader_test";
  std::filesystem::create_directories(dir);
  std::filesystem::path file = dir / name;
  std::FILE* f = std::fopen(file.string().c_str(), "wb");
  REQUIRE(f);
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
  return file.string();
}

/// "line:col code" of every diagnostic (notes: "line:col note").
std::vector<std::string> where(const LoadedFile& f) {
  std::vector<std::string> out;
  for (const Diagnostic& d : f.diags.all())
    out.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + " " +
                  (d.severity == Severity::Note ? std::string("note") : d.code));
  return out;
}

}  // namespace

TEST_CASE("a program whose compact form fills several chunks reads back whole", "[check]") {
  // Chunks grow on the heap to 512 KiB, then are 2 MiB of large memory each: this program's
  // statements take several of both, and each must read back as parsed, across every boundary.
  std::string text;
  for (int i = 0; i < 60000; ++i) {
    text += "v" + std::to_string(i % 97) + " = " + std::to_string(i) + " * w + sqrt(" + std::to_string(i % 13) + ")\n";
    if (i % 3 == 0) text += "if v1 > " + std::to_string(i) + " then print \"line " + std::to_string(i) + "\", v2\n";
  }
  std::string file = writeProgram("many_chunks.bas", text);
  LoadedFile trees = loadFile(file, CompileOptions{}, false);
  REQUIRE(trees.program);
  const std::vector<ast::Stmt*>& stmts = trees.program->stmts;
  ast::CompactStmts store(trees.program->sources);
  for (const ast::Stmt* s : stmts) store.add(*s);
  CHECK(store.bytes() > (size_t{3} << 20));
  ast::Arena scratch;
  ast::StmtCursor c(store, scratch);
  size_t differ = 0;
  for (const ast::Stmt* want : stmts) {
    scratch.reset();
    if (!sameStmt(c.next(), want)) ++differ;
  }
  CHECK(differ == 0);
  CHECK(c.done());
}

TEST_CASE("rb check's compact walk still sees what lies ahead and what is still open", "[check]") {
  // Forward references need what loading gathered: a sub called before its definition (its
  // parameter count), a label defined after its gosub, an array dimmed after the sub that
  // reads it (arrays are global). A block stays open across many statements: its opening
  // statement (a while's condition is compiled at its wend) must outlive them.
  std::string body;
  for (int i = 0; i < 600; ++i) body += "  total = total + " + std::to_string(i) + "\n";
  std::string text =
      "total = 0\n"                           // 1
      "gosub Later\n"                         // 2
      "call Fill(1, 2)\n"                     // 3: Fill takes 1 argument
      "gosub Nowhere\n"                       // 4: no such label
      "while nothing(total) < 3\n" +          // 5: no such function, found at the wend
      body +                                  // 6..605
      "wend\n"                                // 606
      "Later:\n"                              // 607
      "  return\n"                            // 608
      "sub Fill(n)\n"                         // 609
      "  for i = 1 to n\n"                    // 610
      "    total = total + table[i] + kept\n" // 611: table is global; kept is never assigned
      "  next\n"                              // 612
      "endsub\n"                              // 613
      "dim table[3]\n"                        // 614
      "if total > 3\n"                        // 615: never closed
      "  print total\n";                      // 616
  std::string file = writeProgram("ahead.bas", text);
  LoadedFile trees = loadFile(file, CompileOptions{}, true);
  CompileOptions dropped;
  dropped.keepCode = false;
  LoadedFile compact = loadFile(file, dropped, true, true);
  std::vector<std::string> want = {"3:14 rb-argument-count", "4:7 rb-undefined-label",
                                   "5:7 rb-unknown-function", "611:32 rb-unassigned-variable",
                                   "615:1 rb-unclosed-if"};
  std::vector<std::string> got = where(compact);
  std::vector<std::string> gotCodes;
  for (const std::string& w : got)
    if (w.find(" note") == std::string::npos) gotCodes.push_back(w);
  CHECK(gotCodes == want);
  CHECK(allDiagnostics(compact) == allDiagnostics(trees));
}

TEST_CASE("rb check's compact form keeps included files' statements where they are included", "[check]") {
  std::string lib = writeProgram("lib_part.bas",
                                 "Helper:\n"
                                 "  shared = shared + 1\n"
                                 "  return\n"
                                 "sub Twice(v, &r)\n"
                                 "  r = v * 2\n"
                                 "endsub\n");
  std::string text = "#include \"lib_part.bas\"\n"
                     "shared = 0\n"
                     "gosub Helper\n"
                     "call Twice(shared, out)\n"
                     "call Twice(1)\n"
                     "print out + undefinedName\n";
  std::string file = writeProgram("includes.bas", text);
  LoadedFile trees = loadFile(file, CompileOptions{}, true);
  LoadedFile compact = loadFile(file, CompileOptions{}, true, true);
  CHECK(compact.program->sources.size() == 2);
  CHECK(compact.program->stmtCount() == trees.program->stmts.size());
  CHECK(compact.diags.errorCount() == 1);    // Twice takes 2 arguments
  CHECK(compact.diags.warningCount() == 1);  // undefinedName
  CHECK(allDiagnostics(compact) == allDiagnostics(trees));
  (void)lib;
}
