#include "lang/portable_check.h"

#include <cctype>
#include <initializer_list>
#include <string>
#include <string_view>

#include "lang/builtins.h"

namespace rb {

namespace {

constexpr const char* kRule = "rb-not-portable";

/// A form of rb's syntax that no public RobotBASIC source shows and the research notes do not
/// recall either, and what the sources show instead (with where), or nullptr when they show
/// nothing that does the same. Forms the notes recall from RobotBASIC's documentation (tag [R]:
/// `step`, `continue`, `'`, `rem` and `/* */` comments, language.md 1.2, 4.5, 4.8) are not
/// warned about, as recalled names are not.
struct Form {
  const char* what;
  const char* instead;
};

constexpr Form kElseIf{"'else if'", "elseif (course cheat sheet; course lab 3 programs)"};
constexpr Form kEndIf{"'end if'", "endif (seed, Figure 1.13)"};
constexpr Form kEndSub{"closing a sub with 'endsub' or 'end sub'", nullptr};
constexpr Form kIfThen{"'then' at the end of a block if",
                       "if with nothing after the condition (course cheat sheet; course lab 2)"};
constexpr Form kElseIfThen{"'then' after elseif",
                           "elseif with nothing after the condition (course cheat sheet; course lab 3 programs)"};
constexpr Form kLineElse{"'else' in a single-line if",
                         "a block if ... else ... endif (seed, Figure 1.13)"};
constexpr Form kAfterLabel{"a statement on a label's line", "the label alone on its line (seed, Figure 1.9)"};
constexpr Form kNextName{"a variable after next", "next alone (seed, Figure 1.6; course lab 2)"};
constexpr Form kDimScalar{"dim of a name without brackets", "an assignment: name = 0"};
constexpr Form kMod{"the 'mod' operator", "% (C-style operators)"};
constexpr Form kNoCall{"calling a sub without 'call'", "call Name(arguments) (SERVO, December 2013)"};
constexpr Form kSubValue{"a sub's value in an expression", nullptr};
constexpr Form kReturnValue{"'return' with a value", nullptr};

bool wordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '$'; }

/// The parts one after the other (GCC 12 warns falsely about "a" + std::string + "b").
std::string join(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out += p;
  return out;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

class Checker {
 public:
  Checker(const LoadedProgram& program, DiagnosticList& diags)
      : program_(program), builtins_(program.builtins), diags_(diags) {}

  void run() {
    ast::Arena scratch;
    for (ast::StmtCursor c = program_.cursor(scratch); !c.done();) {
      scratch.reset();
      const ast::Stmt* s = c.next();
      statement(*s);
      if (s->kind == ast::StmtKind::Label) {
        label_ = s->loc;
      } else {
        if (label_.valid() && s->loc.file == label_.file && s->loc.line == label_.line)
          form(s->loc, kAfterLabel);
        label_ = {};
      }
    }
  }

 private:
  void warn(SourceLoc loc, std::string message, const char* instead) {
    diags_.warning(loc, std::move(message), kRule);
    if (instead) diags_.note({}, join({"what RobotBASIC is known to have instead: ", instead}));
  }
  void form(SourceLoc loc, const Form& f) {
    warn(loc, join({f.what, " is rb's own: no public RobotBASIC source shows it"}), f.instead);
  }
  void name(SourceLoc loc, const Builtin* b) {
    if (!b || !b->evidence.own()) return;
    std::string instead(b->evidence.instead);
    warn(loc, join({"'", b->name, "' is rb's own: no public RobotBASIC source names it"}),
         instead.empty() ? nullptr : instead.c_str());
  }

  /// The word at `loc`, lower case ("" when none).
  std::string wordAt(SourceLoc loc) const {
    if (!loc.valid() || loc.file >= program_.sources.size()) return {};
    std::string_view line = program_.sources.file(loc.file).lineText(loc.line);
    size_t i = loc.col ? loc.col - 1 : 0, j = i;
    while (j < line.size() && wordChar(line[j])) ++j;
    return i < line.size() ? lower(line.substr(i, j - i)) : std::string();
  }
  /// The position of the first word after the character at `end` on its line, and the word.
  std::pair<SourceLoc, std::string> wordAfter(SourceLoc end) const {
    if (!end.valid() || end.file >= program_.sources.size()) return {};
    std::string_view line = program_.sources.file(end.file).lineText(end.line);
    size_t i = end.col;  // just past the 1-based column `end`
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    SourceLoc at{end.file, end.line, static_cast<uint32_t>(i + 1)};
    return {at, wordAt(at)};
  }

  /// The `else` keyword right before the statement at `at` on its line (`at` when not found).
  SourceLoc elseBefore(SourceLoc at) const {
    std::string_view line = program_.sources.file(at.file).lineText(at.line);
    size_t j = at.col ? at.col - 1 : 0;
    while (j > 0 && (line[j - 1] == ' ' || line[j - 1] == '\t')) --j;
    if (j >= 4 && lower(line.substr(j - 4, 4)) == "else" && (j == 4 || !wordChar(line[j - 5])))
      at.col = static_cast<uint32_t>(j - 3);
    return at;
  }

  void statement(const ast::Stmt& s) {
    using K = ast::StmtKind;
    switch (s.kind) {
      case K::Command:
        name(s.loc, builtins_.find(s.name, BuiltinKind::Command));
        break;
      case K::If:
        if (s.value && wordAfter(s.value->end).second == "then") form(wordAfter(s.value->end).first, kIfThen);
        break;
      case K::ElseIf:
        if (wordAt(s.loc) == "else") form(s.loc, kElseIf);
        if (s.value && wordAfter(s.value->end).second == "then")
          form(wordAfter(s.value->end).first, kElseIfThen);
        break;
      case K::IfLine:
        if (s.body.size() > 1) form(elseBefore(s.body[1]->loc), kLineElse);
        break;
      case K::EndIf:
        if (wordAt(s.loc) == "end") form(s.loc, kEndIf);
        break;
      case K::EndSub:
        form(s.loc, kEndSub);
        break;
      case K::Next:
        if (!s.name.empty()) form(s.nameLoc.valid() ? s.nameLoc : s.loc, kNextName);
        break;
      case K::Call:
        if (wordAt(s.loc) != "call") form(s.loc, kNoCall);
        break;
      case K::Return:
        if (s.value) form(s.loc, kReturnValue);  // only a sub's return has one
        break;
      case K::Dim:
        for (const ast::Expr* e : s.exprs)
          if (e->kind == ast::ExprKind::Var) form(e->loc, kDimScalar);
        break;
      default:
        break;
    }
    expr(s.target);
    expr(s.value);
    for (const ast::Expr* e : s.exprs) expr(e);
    for (const ast::Stmt* b : s.body) statement(*b);
  }

  void expr(const ast::Expr* e) {
    if (!e) return;
    switch (e->kind) {
      case ast::ExprKind::Call: {
        const Builtin* b = builtins_.find(e->text, BuiltinKind::Function);
        if (b) name(e->loc, b);
        else form(e->loc, kSubValue);
        break;
      }
      case ast::ExprKind::Var:
        name(e->loc, builtins_.find(e->text, BuiltinKind::Constant));
        break;
      case ast::ExprKind::Binary:
        if (e->op == Tok::KwMod) form(e->loc, kMod);
        break;
      default:
        break;
    }
    for (const ast::Expr* a : e->args) expr(a);
  }

  const LoadedProgram& program_;
  const BuiltinTable& builtins_;
  DiagnosticList& diags_;
  SourceLoc label_;  ///< the label the statement before was, on its line
};

}  // namespace

void checkPortable(const LoadedProgram& program, DiagnosticList& diags) { Checker(program, diags).run(); }

}  // namespace rb
