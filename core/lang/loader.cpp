#include "lang/loader.h"

#include <filesystem>
#include <set>

#include "base/source.h"
#include "lang/parser.h"

namespace rb {

namespace {

constexpr int kMaxIncludeDepth = 32;

class Loader {
 public:
  Loader(LoadedProgram& out, SourceReader& reader, const LoadOptions& options,
         DiagnosticList& diags)
      : out_(out), reader_(reader), options_(options), diags_(diags) {}

  void loadMain(const std::string& name, std::string text) {
    if (auto canonical = reader_.find(name)) seen_.insert(*canonical);
    if (options_.compact) out_.compact = std::make_unique<ast::CompactStmts>(out_.sources);
    addAndParse(name, std::move(text), SourceLoc{}, 0);
    out_.subSpans = spans_.finish(out_.stmtCount());
  }

 private:
  /// Parses a file line by line; an #include brings its file's statements in at once, where
  /// the directive stands (each file once).
  void parseFile(uint32_t index, int depth) {
    ast::Arena lineArena;  // compact: the trees of one line at a time
    ast::Arena& arena = out_.compact ? lineArena : out_.arena;
    rb::parseFileLines(out_.sources, index, arena, out_.builtins, diags_,
                       [&](const std::vector<ast::Stmt*>& line) {
      for (ast::Stmt* s : line) {
        if (s->kind == ast::StmtKind::Include) include(*s, index, depth);
        else keep(*s);
      }
      if (out_.compact) lineArena.reset();
    });
  }

  /// Adds a statement to the program, noting what is declared in it.
  void keep(ast::Stmt& s) {
    spans_.add(s, out_.stmtCount());
    ast::addArrayNames(s, out_.arrays);
    if (s.kind == ast::StmtKind::Label || s.kind == ast::StmtKind::Sub)
      out_.declarations.push_back(Declaration{s.kind, s.broken, s.name, s.loc, s.nameLoc, s.params});
    if (out_.compact) out_.compact->add(s);
    else out_.stmts.push_back(&s);
  }

  void include(const ast::Stmt& s, uint32_t from, int depth) {
    std::string wanted(s.name);
    if (depth + 1 > kMaxIncludeDepth) {
      diags_.error(s.nameLoc, "includes nested too deeply (more than " +
                                  std::to_string(kMaxIncludeDepth) + " levels)",
                   "rb-include-depth");
      return;
    }
    namespace fs = std::filesystem;
    std::vector<std::string> candidates;
    fs::path wantedPath(wanted);
    if (wantedPath.is_absolute()) {
      candidates.push_back(wanted);
    } else {
      fs::path dir = fs::path(out_.sources.file(from).name()).parent_path();
      candidates.push_back((dir / wantedPath).lexically_normal().string());
      for (const std::string& lib : options_.libraryDirs)
        candidates.push_back((fs::path(lib) / wantedPath).lexically_normal().string());
    }
    std::optional<std::string> found;
    std::string display;
    for (const std::string& c : candidates) {
      found = reader_.find(c);
      if (found) {
        display = c;
        break;
      }
    }
    if (!found) {
      diags_.error(s.nameLoc, "include file '" + wanted + "' not found", "rb-include-not-found");
      return;
    }
    if (std::string why = reader_.refusal(*found); !why.empty()) {
      diags_.error(s.nameLoc, "cannot #include '" + wanted + "': " + why, "rb-include-refused");
      return;
    }
    if (!seen_.insert(*found).second) return;  // each file once
    std::optional<std::string> text = reader_.read(*found);
    if (!text) {
      diags_.error(s.nameLoc, "cannot read include file '" + wanted + "'", "rb-include-unreadable");
      return;
    }
    addAndParse(display, std::move(*text), s.loc, depth + 1);
  }

  /// Decodes a file's bytes (BOM, Windows-1252), adds it to the program and parses it; a file
  /// that is not text is reported once and not parsed.
  void addAndParse(const std::string& name, std::string raw, SourceLoc includedFrom, int depth) {
    DecodedText decoded = decodeSourceText(std::move(raw));
    uint32_t index = out_.sources.add(name, std::move(decoded.text), includedFrom);
    if (decoded.kind == DecodedText::Binary) {
      diags_.error(SourceLoc{index, 0, 0},
                   "this is a binary file, not a program (it holds " + decoded.why + ")",
                   "rb-binary-input");
      return;
    }
    parseFile(index, depth);
  }

  LoadedProgram& out_;
  SourceReader& reader_;
  const LoadOptions& options_;
  DiagnosticList& diags_;
  std::set<std::string> seen_;
  ast::SubSpanFinder spans_;
};

}  // namespace

std::unique_ptr<LoadedProgram> loadProgram(const std::string& name, std::string text,
                                           SourceReader& reader, const BuiltinTable& builtins,
                                           const LoadOptions& options, DiagnosticList& diags) {
  auto out = std::make_unique<LoadedProgram>(builtins);
  Loader(*out, reader, options, diags).loadMain(name, std::move(text));
  return out;
}

}  // namespace rb
