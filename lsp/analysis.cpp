#include "analysis.h"

#include <filesystem>

#include "lang/ast_walk.h"
#include "lang/checker.h"
#include "lang/compiler.h"
#include "lang/lexer.h"
#include "lang/portable_check.h"

namespace rb::lsp {

namespace {

struct Directive {
  SourceLoc loc;
  std::string wanted;
};

/// The `#include "x"` lines of the main file, in order.
std::vector<Directive> mainDirectives(const SourceSet& sources) {
  DiagnosticList ignored;
  std::vector<Token> tokens = lex(sources, 0, ignored);
  std::vector<Directive> out;
  for (size_t i = 0; i + 2 < tokens.size(); ++i) {
    if (tokens[i].kind != Tok::Hash || tokens[i + 1].kind != Tok::Ident ||
        tokens[i + 2].kind != Tok::String)
      continue;
    std::string word(tokens[i + 1].text);
    for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (word == "include") out.push_back({tokens[i].loc, std::string(tokens[i + 2].text)});
  }
  return out;
}

/// Which directive of the main file loaded each file. Files are numbered in the order the loader
/// reads them (depth first), so a file belongs to the last directive of the main file that
/// loaded a file at or before it.
std::vector<SourceLoc> includeOwners(const SourceSet& sources, const LoadOptions& options) {
  namespace fs = std::filesystem;
  std::vector<SourceLoc> owner(sources.size());
  std::vector<Directive> directives = mainDirectives(sources);
  fs::path dir = fs::path(sources.file(0).name()).parent_path();
  size_t next = 1;
  std::vector<std::pair<size_t, SourceLoc>> starts;
  for (const Directive& d : directives) {
    fs::path wanted(d.wanted);
    std::vector<std::string> candidates;
    if (wanted.is_absolute()) {
      candidates.push_back(d.wanted);
    } else {
      candidates.push_back((dir / wanted).lexically_normal().string());
      for (const std::string& lib : options.libraryDirs)
        candidates.push_back((fs::path(lib) / wanted).lexically_normal().string());
    }
    for (size_t k = next; k < sources.size(); ++k) {
      bool match = false;
      for (const std::string& c : candidates) match = match || sources.file(k).name() == c;
      if (match) {
        starts.push_back({k, d.loc});
        next = k + 1;
        break;
      }
    }
  }
  for (size_t k = 1; k < sources.size(); ++k) {
    for (const auto& [start, loc] : starts)
      if (start <= k) owner[k] = loc;
  }
  return owner;
}

}  // namespace

int Analysis::scopeAt(uint32_t line) const {
  for (size_t i = 0; i < symbols.size(); ++i) {
    const Symbol& s = symbols[i];
    if (s.kind == Symbol::Kind::Sub && s.loc.file == 0 && s.loc.line <= line && line <= s.end.line)
      return static_cast<int>(i);
  }
  return -1;
}

std::string Symbol::signature() const {
  if (kind == Kind::Label) return name + ":";
  std::string s = "sub " + name + "(";
  for (size_t i = 0; i < params.size(); ++i) {
    if (i) s += ", ";
    s += params[i];
  }
  return s + ")";
}

std::unique_ptr<Analysis> analyze(const std::string& name, const std::string& text,
                                  SourceReader& reader, const BuiltinTable& builtins,
                                  const LoadOptions& options, bool portable) {
  auto a = std::make_unique<Analysis>();
  a->program = loadProgram(name, text, reader, builtins, options, a->diags);
  compileChecked(*a->program, CompileOptions{}, true, a->diags);  // as rb check does
  if (portable) {  // as rb check --portable does
    checkPortable(*a->program, a->diags);
    a->diags.sort();
  }

  const LoadedProgram& p = *a->program;
  for (size_t k = 1; k < p.sources.size(); ++k) {
    if (auto canonical = reader.find(p.sources.file(static_cast<uint32_t>(k)).name()))
      a->includes.push_back(*canonical);
  }
  a->includedAt = includeOwners(p.sources, options);

  // Subs (with the extent of their bodies), then labels, in program order.
  std::vector<ast::SubSpan> spans = ast::subSpans(p.stmts);
  std::vector<int> subOfStmt(p.stmts.size(), -1);
  for (const ast::SubSpan& span : spans) {
    const ast::Stmt& s = *p.stmts[span.begin];
    Symbol sym;
    sym.kind = Symbol::Kind::Sub;
    sym.name = std::string(s.name);
    sym.loc = s.nameLoc.valid() ? s.nameLoc : s.loc;
    sym.end = s.loc;
    for (size_t i = span.begin; i < span.end && i < p.stmts.size(); ++i) {
      if (p.stmts[i]->loc.file == s.loc.file) sym.end = p.stmts[i]->loc;
    }
    if (span.how == ast::SubEnd::EndSub && span.end < p.stmts.size()) sym.end = p.stmts[span.end]->loc;
    for (const ast::Param& param : s.params) {
      std::string written = param.byRef ? "&" : "";
      written += param.name;
      sym.params.push_back(std::move(written));
    }
    if (!sym.name.empty()) {
      for (size_t i = span.begin; i < span.end && i < p.stmts.size(); ++i)
        subOfStmt[i] = static_cast<int>(a->symbols.size());
      a->symbols.push_back(std::move(sym));
    }
  }
  for (size_t i = 0; i < p.stmts.size(); ++i) {
    const ast::Stmt& s = *p.stmts[i];
    if (s.kind != ast::StmtKind::Label || s.name.empty()) continue;
    Symbol sym;
    sym.kind = Symbol::Kind::Label;
    sym.name = std::string(s.name);
    sym.loc = sym.end = s.nameLoc.valid() ? s.nameLoc : s.loc;
    sym.container = subOfStmt[i];
    a->symbols.push_back(std::move(sym));
  }

  auto noByRef = [](std::string_view, size_t) { return false; };
  for (size_t i = 0; i < p.stmts.size(); ++i) {
    const ast::Stmt* s = p.stmts[i];
    int scope = subOfStmt[i];
    ast::forEachName(*s, p.builtins, [&](std::string_view n, SourceLoc loc, ast::NameUse) {
      a->variables[std::string(n)].push_back({loc, scope});
    }, noByRef);
    if (s->kind == ast::StmtKind::Sub) {
      for (const ast::Param& param : s->params)
        if (!param.name.empty()) a->variables[std::string(param.name)].push_back({param.loc, scope});
    }
  }
  for (std::string_view n : ast::arrayNames(p.stmts)) a->arrays.insert(std::string(n));
  return a;
}

}  // namespace rb::lsp
