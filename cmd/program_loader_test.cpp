#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "lang/checker.h"
#include "program_loader.h"

using namespace rb;
using namespace rb::cli;

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
