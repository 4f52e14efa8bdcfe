#include "checker.h"

#include <map>
#include <set>
#include <string>
#include <unordered_map>

#include "ast_walk.h"
#include "suggest.h"

namespace rb {

namespace {

struct ScopeUse {
  std::set<std::string_view> written;
  std::map<std::string_view, SourceLoc> firstRead;  // ordered for stable output
};

bool isGlobalRef(std::string_view name) { return name.size() > 1 && name[0] == '_'; }

}  // namespace

void lintProgram(const LoadedProgram& program, DiagnosticList& diags) {
  // Which sub parameters are by reference, for calls.
  std::unordered_map<std::string_view, std::vector<bool>> byRef;
  for (const ast::Stmt* s : program.stmts) {
    if (s->kind != ast::StmtKind::Sub) continue;
    std::vector<bool>& flags = byRef[s->name];
    for (const ast::Param& p : s->params) flags.push_back(p.byRef);
  }
  auto isByRef = [&](std::string_view sub, size_t i) {
    auto it = byRef.find(sub);
    return it != byRef.end() && i < it->second.size() && it->second[i];
  };

  ScopeUse global;
  std::vector<ScopeUse> subs;
  ScopeUse* local = nullptr;
  uint32_t subFile = 0;
  for (const ast::Stmt* s : program.stmts) {
    if (local && s->loc.file != subFile) local = nullptr;  // a sub ends with its file
    if (s->kind == ast::StmtKind::Sub) {
      subFile = s->loc.file;
      subs.emplace_back();
      local = &subs.back();
    } else if (s->kind == ast::StmtKind::EndSub) {
      local = nullptr;
      continue;
    }
    ast::forEachName(*s, [&](std::string_view name, SourceLoc loc, ast::NameUse use) {
      ScopeUse* scope = local && !isGlobalRef(name) ? local : &global;
      if (isGlobalRef(name)) name.remove_prefix(1);
      if (use != ast::NameUse::Read) scope->written.insert(name);
      if (use == ast::NameUse::Read || use == ast::NameUse::ReadWrite) scope->firstRead.try_emplace(name, loc);
    }, isByRef);
  }

  auto report = [&](const ScopeUse& scope, const char* where) {
    std::vector<std::string_view> written(scope.written.begin(), scope.written.end());
    for (const auto& [name, loc] : scope.firstRead) {
      if (scope.written.count(name)) continue;
      std::string msg = "variable '" + std::string(name) + "' is read but never assigned" + where;
      std::string hint = closestMatch(name, written, true);
      if (!hint.empty()) {
        msg += "; did you mean '" + hint + "'?";
        if (editDistance(name, hint, true) == 0) msg += " (names are case-sensitive)";
      }
      diags.warning(loc, msg);
    }
  };
  report(global, "");
  for (const ScopeUse& s : subs) report(s, " in this sub");
}

}  // namespace rb
