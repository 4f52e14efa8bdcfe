#include "lang/checker.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "lang/ast_walk.h"
#include "lang/builtins.h"
#include "lang/flow_check.h"
#include "lang/suggest.h"
#include "lang/value.h"

namespace rb {

namespace {

/// How a scope (the main program or a sub) uses one name.
struct NameUses {
  static constexpr uint32_t kNoNumber = 0xffffffffu;
  bool written = false;
  bool read = false;
  SourceLoc firstRead;
  /// The first read that is a built-in's argument, and its parameter: where a constant may
  /// have been meant (`rPen dwn`).
  const Builtin* argOf = nullptr;
  std::string_view param;
  uint32_t number = kNoNumber;  ///< the variable's number for the flow checks
};

/// A variable standing alone as the argument of a built-in: its position and parameter.
struct ArgumentPlace {
  SourceLoc loc;
  const Builtin* builtin;
  std::string_view param;
};

/// The bare names of `e` (and within it) that are arguments of built-in functions.
void builtinArguments(const ast::Expr* e, const BuiltinTable& builtins, std::vector<ArgumentPlace>& out) {
  if (!e) return;
  if (e->kind == ast::ExprKind::Call) {
    if (const Builtin* b = builtins.find(e->text, BuiltinKind::Function); b && !b->printList) {
      int n = static_cast<int>(e->args.size());
      for (int i = 0; i < n && b->acceptsCount(n); ++i)
        if (e->args[static_cast<size_t>(i)]->kind == ast::ExprKind::Var)
          out.push_back({e->args[static_cast<size_t>(i)]->loc, b, b->param(n, i).name});
    }
  }
  for (const ast::Expr* a : e->args) builtinArguments(a, builtins, out);
}

/// The same for a statement: the arguments of a built-in command and of the functions in it.
void builtinArguments(const ast::Stmt& s, const BuiltinTable& builtins, std::vector<ArgumentPlace>& out) {
  if (s.kind == ast::StmtKind::Command) {
    const Builtin* b = builtins.find(s.name, BuiltinKind::Command);
    int n = static_cast<int>(s.exprs.size());
    if (b && !b->printList && b->acceptsCount(n)) {
      for (int i = 0; i < n; ++i) {
        const ast::Expr* a = s.exprs[static_cast<size_t>(i)];
        if (a->kind == ast::ExprKind::Var && !b->param(n, i).out) out.push_back({a->loc, b, b->param(n, i).name});
      }
    }
  }
  builtinArguments(s.target, builtins, out);
  builtinArguments(s.value, builtins, out);
  for (const ast::Expr* e : s.exprs) builtinArguments(e, builtins, out);
  for (const ast::Stmt* b : s.body) builtinArguments(*b, builtins, out);
}

struct ScopeUse {
  std::unordered_map<std::string_view, NameUses> names;  // reported in the order of names
};

/// Every word that looks like a name on a line that has an error.
std::unordered_set<std::string> namesOnErrorLines(const SourceSet& sources, const DiagnosticList& diags) {
  std::unordered_set<std::string> names;
  auto wordChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '$'; };
  for (const Diagnostic& d : diags.all()) {
    if (d.severity != Severity::Error || !d.loc.valid() || d.loc.file >= sources.size()) continue;
    std::string_view line = sources.file(d.loc.file).lineText(d.loc.line);
    for (size_t i = 0; i < line.size();) {
      if (!wordChar(line[i])) {
        ++i;
        continue;
      }
      size_t j = i;
      while (j < line.size() && wordChar(line[j])) ++j;
      names.insert(std::string(line.substr(i, j - i)));
      i = j;
    }
  }
  return names;
}

}  // namespace

struct Linter::State {
  State(const LoadedProgram& p, const LintOptions& o)
      : program(p), nextSpan(p.subSpans.begin()), flow(p, o.realRobot || o.robotPlaced) {}
  const LoadedProgram& program;
  std::unordered_map<std::string_view, std::vector<bool>> byRef;  ///< sub parameters by reference
  ScopeUse global;
  std::vector<ScopeUse> subs;
  ScopeUse* local = nullptr;      // the sub being read, if any
  bool skip = false;              // a sub whose line had a syntax error: its names are unknown
  std::unordered_set<std::string_view> params;
  std::vector<ast::SubSpan>::const_iterator nextSpan;
  size_t subEnd = 0;
  std::vector<ArgumentPlace> arguments;  ///< of the statement being read
  FlowChecks flow;
  uint32_t variables = 0;  // numbered so far, for the flow checks

  /// The uses of `name` in the scope being read, numbered for the flow checks.
  NameUses& uses(std::string_view name) {
    // Arrays are global: in a sub, an array name is the global array unless it is a parameter.
    bool globalName = ast::isGlobalRef(name) || (program.arrays.count(name) && !params.count(name));
    ScopeUse* scope = local && !globalName ? local : &global;
    std::string_view key = ast::globalName(name);
    NameUses& u = scope->names[key];
    if (u.number == NameUses::kNoNumber) {
      u.number = variables++;
      flow.declareVariable(u.number, scope == &global, key);
    }
    return u;
  }
};

Linter::Linter(const LoadedProgram& program, const LintOptions& options)
    : st_(std::make_unique<State>(program, options)) {
  // Which sub parameters are by reference, for calls.
  for (const Declaration& s : program.declarations) {
    if (s.kind != ast::StmtKind::Sub || s.broken) continue;
    std::vector<bool>& flags = st_->byRef[s.name];
    for (const ast::Param& p : s.params) flags.push_back(p.byRef);
  }
}

Linter::~Linter() = default;

void Linter::statement(const ast::Stmt& s, size_t i) {
  State& st = *st_;
  const std::vector<ast::SubSpan>& spans = st.program.subSpans;
  if ((st.local || st.skip) && i == st.subEnd) {
    st.local = nullptr;
    st.skip = false;
    st.flow.leaveSub();
  }
  if (st.nextSpan != spans.end() && st.nextSpan->begin == i) {
    st.subEnd = st.nextSpan->end;
    st.flow.enterSub(static_cast<size_t>(st.nextSpan - spans.begin()));
    ++st.nextSpan;
    st.params.clear();
    if (s.broken) {
      st.skip = true;
    } else {
      st.subs.emplace_back();
      st.local = &st.subs.back();
      for (const ast::Param& p : s.params) st.params.insert(p.name);
    }
  }
  if (st.skip || s.kind == ast::StmtKind::EndSub) return;
  auto isByRef = [&](std::string_view sub, size_t k) {
    auto it = st.byRef.find(sub);
    return it != st.byRef.end() && k < it->second.size() && it->second[k];
  };
  st.arguments.clear();
  builtinArguments(s, st.program.builtins, st.arguments);
  st.flow.statement(s, [&st](std::string_view name) { return st.uses(name).number; });
  ast::forEachName(s, st.program.builtins, [&](std::string_view name, SourceLoc loc, ast::NameUse use) {
    NameUses& uses = st.uses(name);
    if (use != ast::NameUse::Read) {
      uses.written = true;
      if (s.kind != ast::StmtKind::Sub) st.flow.write(uses.number);  // parameters: given, not set
    }
    if ((use == ast::NameUse::Read || use == ast::NameUse::ReadWrite) && !uses.read) {
      uses.read = true;
      uses.firstRead = loc;
    }
    if (use == ast::NameUse::Read && !uses.argOf) {
      for (const ArgumentPlace& a : st.arguments) {
        if (a.loc != loc) continue;
        uses.argOf = a.builtin;
        uses.param = a.param;
        break;
      }
    }
  }, isByRef);
}

void Linter::finish(DiagnosticList& diags) {
  State& st = *st_;
  // A line with an error was not (or not wholly) understood: any name on it may have been
  // assigned there, so a read of it elsewhere is no news (no cascade from a missing ')').
  std::unordered_set<std::string> onBrokenLines = namesOnErrorLines(st.program.sources, diags);

  auto report = [&](const ScopeUse& scope, const char* where) {
    std::vector<std::string_view> written;
    std::vector<std::pair<std::string_view, const NameUses*>> reads;  // read and never written
    for (const auto& [name, uses] : scope.names) {
      if (uses.written) written.push_back(name);
      else if (uses.read) reads.emplace_back(name, &uses);
    }
    std::sort(written.begin(), written.end());
    std::sort(reads.begin(), reads.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    const BuiltinTable& builtins = st.program.builtins;
    for (const auto& [name, uses] : reads) {
      if (onBrokenLines.count(std::string(name))) continue;
      SourceLoc loc = uses->firstRead;
      std::string msg = "variable '" + std::string(name) + "' is read but never assigned" + where;
      // A variable of the scope, or a constant (first those that fit the argument it is).
      std::vector<std::string_view> fitting;
      if (uses->argOf) fitting = constantsFitting(builtins, *uses->argOf, uses->param);
      std::string hint = suggestValue(name, fitting, written, builtins);
      if (!hint.empty()) {
        msg += "; did you mean '" + hint + "'?";
        if (editDistance(name, hint, true) == 0) msg += " (names are case-sensitive)";
      }
      Diagnostic& d = diags.warning(loc, msg, "rb-unassigned-variable");
      if (!hint.empty())
        d.fixits.push_back({loc, {loc.file, loc.line, loc.col + static_cast<uint32_t>(name.size())}, hint});
    }
  };
  report(st.global, "");
  for (const ScopeUse& s : st.subs) report(s, " in this sub");
  st.flow.finish(diags);
}

void lintProgram(const LoadedProgram& program, DiagnosticList& diags, const LintOptions& options) {
  Linter linter(program, options);
  ast::Arena scratch;  // statements read back from the compact form, one at a time
  for (ast::StmtCursor c = program.cursor(scratch); !c.done();) {
    scratch.reset();
    size_t i = c.index();
    linter.statement(*c.next(), i);
  }
  linter.finish(diags);
}

}  // namespace rb

namespace rb {

namespace {

/// The RB-9 moves at most about this much per rForward (seed document, "Limitations").
constexpr double kRb9MaxMove = 250;

/// The value of a constant numeric argument (a literal, or a negated one), if it is one.
std::optional<double> constantNumber(const ast::Expr* e) {
  if (!e) return std::nullopt;
  if (e->kind == ast::ExprKind::Int) return static_cast<double>(e->ival);
  if (e->kind == ast::ExprKind::Float) return e->dval;
  if (e->kind == ast::ExprKind::Unary && e->op == Tok::Minus && e->args.size() == 1) {
    std::optional<double> v = constantNumber(e->args[0]);
    if (v) return -*v;
  }
  return std::nullopt;
}

/// Why a built-in function has nothing behind it on the RB-9, or "" when it does.
std::string missingOnRb9(std::string_view name) {
  if (name == "rLook") return "rLook(): the RB-9 has no camera, so the real robot cannot report colours";
  if (name == "rGPSX" || name == "rGPSY")
    return std::string(name) + "(): the RB-9 has no GPS; track the position from its moves and rCompass()";
  if (name == "rChargeLevel")
    return "rChargeLevel(): the robot protocol has no battery command, so this stops the program "
           "on a real robot";
  return "";
}

void checkExpr(const ast::Expr* e, const BuiltinTable& builtins, DiagnosticList& diags) {
  if (!e) return;
  if (e->kind == ast::ExprKind::Call) {
    if (const Builtin* b = builtins.find(e->text, BuiltinKind::Function)) {
      std::string why = missingOnRb9(b->name);
      if (!why.empty()) diags.warning(e->loc, why, "rb-rb9-unsupported");
    }
  }
  for (const ast::Expr* a : e->args) checkExpr(a, builtins, diags);
}

void checkStmt(const ast::Stmt* s, const BuiltinTable& builtins, DiagnosticList& diags) {
  if (s->kind == ast::StmtKind::Command && !s->exprs.empty()) {
    const Builtin* b = builtins.find(s->name, BuiltinKind::Command);
    std::optional<double> n = constantNumber(s->exprs[0]);
    if (b && b->name == "rForward" && n && std::abs(*n) > kRb9MaxMove)
      diags.warning(s->loc, "rForward " + formatNumber(*n) +
                                ": the RB-9 moves at most about 250 per command (the seed "
                                "recommends staying below 200); use several shorter moves",
                    "rb-rb9-long-move");
  }
  checkExpr(s->target, builtins, diags);
  checkExpr(s->value, builtins, diags);
  for (const ast::Expr* e : s->exprs) checkExpr(e, builtins, diags);
  for (const ast::Stmt* b : s->body) checkStmt(b, builtins, diags);
}

}  // namespace

void checkRb9Target(const LoadedProgram& program, DiagnosticList& diags) {
  ast::Arena scratch;
  for (ast::StmtCursor c = program.cursor(scratch); !c.done();) {
    scratch.reset();
    checkStmt(c.next(), program.builtins, diags);
  }
}

std::unique_ptr<Program> compileChecked(const LoadedProgram& program, const CompileOptions& options, bool lint,
                                        DiagnosticList& diags, const LintOptions& lintOptions) {
  std::unique_ptr<Program> compiled;
  if (lint) {
    // One walk over the program for both.
    Linter linter(program, lintOptions);
    CompileOptions withLint = options;
    withLint.onStatement = [&linter](const ast::Stmt& s, size_t i) { linter.statement(s, i); };
    compiled = compileProgram(program, withLint, diags);
    linter.finish(diags);
  } else {
    compiled = compileProgram(program, options, diags);
  }
  diags.sort();
  return compiled;
}

}  // namespace rb
