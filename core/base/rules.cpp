#include "base/rules.h"

#include <algorithm>

#ifndef RB_DOCS_URL
#define RB_DOCS_URL "https://github.com/OWNER/rb/blob/main/docs/"
#endif

namespace rb {

namespace {

// Every rule code rb reports. A new rule is one row here; docs/diagnostics.md's table is
// generated from this (scripts/gen_rules_doc.py) and testdata/diagnostics/diag_test.py's
// "rules" test fails when a code used in the sources is missing.
constexpr Rule kRules[] = {
    {"rb-unreadable-file", Severity::Error,
     "A program file could not be read.",
     "The file does not exist, is a folder, or is larger than 16 MiB."},
    {"rb-binary-input", Severity::Error,
     "The file is binary data, not program text.",
     "The file is binary data, not program text ([Input that is not a program](#input-that-is-not-a-program))."},
    {"rb-unexpected-character", Severity::Error,
     "A character that is not part of RobotBASIC.",
     "A character that is not part of RobotBASIC."},
    {"rb-unterminated-comment", Severity::Error,
     "A /* comment that never closes.",
     "A `/*` comment that never closes."},
    {"rb-unterminated-string", Severity::Error,
     "A string without its closing quote on the same line.",
     "A string without its closing quote on the same line."},
    {"rb-number-too-large", Severity::Error,
     "A hexadecimal or binary literal that does not fit in 64 bits.",
     "A hexadecimal or binary literal beyond 64 bits."},
    {"rb-syntax", Severity::Error,
     "The line does not follow RobotBASIC's grammar.",
     "The line does not follow the grammar (\"expected ..., found ...\")."},
    {"rb-missing-operator", Severity::Error,
     "Two values side by side with no operator or separator between them.",
     "Two values side by side with nothing between them (`print \"moves: \" n`, `total = 2 n`): which operator or separator is missing, with a fix-it that inserts it ([Values side by side](#values-side-by-side))."},
    {"rb-unknown-directive", Severity::Error,
     "A # line other than #include.",
     "A `#` line other than `#include`."},
    {"rb-nesting-too-deep", Severity::Error,
     "An expression nested more than 200 levels deep.",
     "An expression nested more than 200 levels."},
    {"rb-block-in-line-if", Severity::Error,
     "A block statement (for, while, ...) inside a single-line if.",
     "`for`, `while`, ... inside a single-line `if`."},
    {"rb-unknown-command", Severity::Error,
     "A statement that is neither a command, a sub nor an assignment.",
     "A statement that is no command, sub or assignment (with a did-you-mean)."},
    {"rb-unknown-function", Severity::Error,
     "A call of a function that is neither built in nor a sub.",
     "A call of a function that is neither built in nor a sub."},
    {"rb-misplaced-builtin", Severity::Error,
     "A built-in's name where it cannot stand (assigned, used as a label, ...).",
     "A built-in's name where it cannot stand (assigned to, a sub's name, ...): which built-in, and a free name to use instead."},
    {"rb-duplicate-label", Severity::Error,
     "Two labels with the same name.",
     "Two labels with one name (a note shows the first)."},
    {"rb-duplicate-sub", Severity::Error,
     "Two subs with the same name.",
     "Two subs with one name."},
    {"rb-duplicate-parameter", Severity::Error,
     "A sub parameter named twice.",
     "A parameter named twice in one sub."},
    {"rb-label-is-sub", Severity::Error,
     "A label with the name of a sub.",
     "A label with the name of a sub."},
    {"rb-sub-as-label", Severity::Error,
     "goto or gosub to a sub (subs are called with call).",
     "`goto`/`gosub` to a sub (subs are called with `call`)."},
    {"rb-unmatched-block", Severity::Error,
     "A block closer (next, wend, endif, ...) that does not match the open block.",
     "A closer (`next`, `wend`, `endif`, `else`, ...) without its opener, or closing the wrong block."},
    {"rb-unclosed-block", Severity::Error,
     "A loop or sub that is never closed.",
     "A loop never closed before the end of the file or the next sub."},
    {"rb-outside-loop", Severity::Error,
     "break or continue outside a loop.",
     "`break` or `continue` outside a loop."},
    {"rb-undefined-label", Severity::Error,
     "goto or gosub to a label that does not exist.",
     "`goto`/`gosub` to a label that does not exist (with a did-you-mean)."},
    {"rb-too-many-arguments", Severity::Error,
     "More than 65535 items in one statement.",
     "More than 65535 items in one statement."},
    {"rb-too-many-indices", Severity::Error,
     "An array index with more than 64 dimensions.",
     "More than 64 array dimensions."},
    {"rb-program-too-large", Severity::Error,
     "More than 67,108,864 variables, constants or temporaries in one place.",
     "More than 67,108,864 variables, constants or temporaries in one place (the interpreter addresses slots with 26 bits), or more than 268,435,456 instructions (it finds a jump's target as a byte offset in 32 bits)."},
    {"rb-argument-count", Severity::Error,
     "A built-in or sub called with the wrong number of arguments.",
     "A built-in or sub called with the wrong number of arguments (the usage line, or the sub, as a note)."},
    {"rb-output-argument", Severity::Error,
     "A built-in's output argument that is not a variable.",
     "A built-in's output argument that is not a variable."},
    {"rb-reference-argument", Severity::Error,
     "A by-reference (&) sub argument that is not a variable.",
     "A by-reference (`&`) argument that is not a variable."},
    {"rb-return-outside-sub", Severity::Error,
     "return with a value outside a sub.",
     "`return` with a value outside a sub."},
    {"rb-include-depth", Severity::Error,
     "#include nested more than 32 files deep.",
     "`#include` nested more than 32 files deep."},
    {"rb-include-not-found", Severity::Error,
     "An #include file that does not exist.",
     "An `#include` file found neither beside the program nor in the library folders."},
    {"rb-include-refused", Severity::Error,
     "An #include file outside the program's folder and the library folders.",
     "An `#include` file outside the program's folder tree and the library folders (and the folders `--allow-files` names): nothing of it is read ([confinement.md](confinement.md))."},
    {"rb-too-many-errors", Severity::Error,
     "More than 10,000 errors: the rest of the program is not checked.",
     "More than 10,000 errors: rb stops reading and compiling the program there, in every command (a file of a million broken lines is rejected in a moment, not after minutes and gigabytes). Fix the first errors and check again."},
    {"rb-include-unreadable", Severity::Error,
     "An #include file that exists but cannot be read.",
     "An `#include` file that exists but cannot be read."},
    {"rb-unclosed-if", Severity::Warning,
     "An if without endif: the block runs to the end of the file or sub.",
     "An `if` without `endif`: the block runs to the end of the file or sub (RobotBASIC runs such programs)."},
    {"rb-unassigned-variable", Severity::Warning,
     "A variable that is read but never assigned.",
     "A variable read but never assigned in its scope, often a case slip (`real` for `Real`) or a misspelt constant (`rPen dwn`: did you mean `Down`?)."},
    {"rb-endless-loop", Severity::Warning,
     "A while or repeat loop whose condition nothing in the loop changes.",
     "A `while` or `repeat` loop whose condition tests variables that nothing in the loop changes ([Loops that never end](#loops-that-never-end))."},
    {"rb-robot-not-placed", Severity::Warning,
     "A robot statement or sensor that runs before rLocate places the robot.",
     "A robot statement or sensor that every way to it reaches before `rLocate` ([The robot before rLocate](#the-robot-before-rlocate))."},
    {"rb-jump-into-sub", Severity::Warning,
     "goto or gosub to a label inside a sub, from outside that sub.",
     "`goto`/`gosub` to a label inside a sub, from outside that sub ([Jumps into subs, unused subs and labels](#jumps-into-subs-unused-subs-and-labels))."},
    {"rb-unused-sub", Severity::Warning,
     "A sub that is never called.",
     "A sub of the checked file that nothing calls."},
    {"rb-unused-label", Severity::Warning,
     "A label that no goto or gosub jumps to.",
     "A label of the checked file that no `goto`/`gosub` names and that the code before it does not reach: the code after it never runs."},
    {"rb-rb9-unsupported", Severity::Warning,
     "A function the RB-9 robot has nothing behind (rb check --target rb9).",
     "With `--target rb9`: a function the RB-9 robot has nothing behind."},
    {"rb-rb9-long-move", Severity::Warning,
     "A move longer than the RB-9 makes in one command (rb check --target rb9).",
     "With `--target rb9`: a move longer than the RB-9 makes in one command."},
    {"rb-not-portable", Severity::Warning,
     "A name or statement form no public RobotBASIC source shows (rb check --portable).",
     "With `--portable` (the language server: `rb.portable`): a built-in that is rb's own, or a statement form rb accepts beyond RobotBASIC's sources, with a note saying what RobotBASIC is known to have instead where there is one ([Portable programs](#portable-programs))."},
    {"rb-runtime-error", Severity::Error,
     "The program stopped with an error while running.",
     "The program stopped with an error while it ran (`rb run`)."},
    {"rb-robot-crash", Severity::Error,
     "The robot ran into something while the program ran.",
     "The simulated robot ran into something (`rb run`)."},
    {"rb-limit", Severity::Error,
     "The run was stopped by --max-steps or --timeout.",
     "Reserved for runs stopped by `--max-steps` or `--timeout` (those messages carry no code yet)."},
};

/// "[text](target)" -> text or "[text](base + target)"; "`code`" -> code when plain.
std::string rewrite(std::string_view md, bool plain) {
  std::string out;
  for (size_t i = 0; i < md.size(); ++i) {
    char c = md[i];
    if (c == '`' && plain) continue;
    if (c == '[') {
      size_t close = md.find("](", i);
      size_t end = close == std::string_view::npos ? close : md.find(')', close);
      if (end != std::string_view::npos) {
        std::string_view text = md.substr(i + 1, close - i - 1);
        std::string_view target = md.substr(close + 2, end - close - 2);
        if (plain) {
          for (char t : text)
            if (t != '`') out += t;
        } else {
          out += '[';
          out += text;
          out += "](";
          bool absolute = target.find("://") != std::string_view::npos;
          if (!absolute) out += docsBaseUrl();
          if (!absolute && !target.empty() && target[0] == '#') out += "diagnostics.md";
          out += target;
          out += ')';
        }
        i = end;
        continue;
      }
    }
    out += c;
  }
  return out;
}

}  // namespace

std::span<const Rule> allRules() { return kRules; }

const Rule* findRule(std::string_view id) {
  auto it = std::find_if(std::begin(kRules), std::end(kRules), [&](const Rule& r) { return r.id == id; });
  return it == std::end(kRules) ? nullptr : it;
}

std::string_view docsBaseUrl() { return RB_DOCS_URL; }

std::string ruleUrl(std::string_view id) {
  return std::string(docsBaseUrl()) + "diagnostics.md#" + std::string(id);
}

std::string ruleText(const Rule& rule) { return rewrite(rule.description, true); }

std::string ruleMarkdown(const Rule& rule) { return rewrite(rule.description, false); }

}  // namespace rb
