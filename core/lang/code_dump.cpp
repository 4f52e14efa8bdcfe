#include "lang/code_dump.h"

#include <cstdio>
#include <map>
#include <set>

#include "lang/builtins.h"

namespace rb {

namespace {

/// Writes the dump of one program.
class Dumper {
 public:
  Dumper(const Program& p, const SourceSet& sources) : p_(p), sources_(sources) {}

  std::string run() {
    header();
    for (const SubInfo& s : p_.subs) subAt_[s.entry] = &s;
    for (const LabelEntry& l : p_.labels) labelsAt_.emplace(l.pc, l.name);
    for (const Instr& in : p_.code)
      if (hasJumpTarget(in.op)) targets_.insert(jumpTarget(in));
    out_ += "\nmain\n";
    for (uint32_t pc = 0; pc < p_.code.size(); ++pc) {
      if (sub_ && pc >= sub_->end) {
        sub_ = nullptr;
        out_ += "\nmain\n";
      }
      if (auto it = subAt_.find(pc); it != subAt_.end()) subHeader(*it->second);
      auto [first, last] = labelsAt_.equal_range(pc);
      for (auto it = first; it != last; ++it) out_ += it->second + ":\n";
      sourceLine(pc);
      instruction(pc);
    }
    return out_;
  }

 private:
  void header() {
    out_ += "globals   ";
    for (uint32_t i = 0; i < p_.globalNames.size(); ++i)
      out_ += (i ? ", g" : " g") + std::to_string(i) + " " + p_.globalNames[i];
    if (p_.globalNames.empty()) out_ += " (none)";
    out_ += "\nconstants ";
    for (uint32_t i = 0; i < p_.constants.size(); ++i)
      out_ += (i ? ", k" : " k") + std::to_string(i) + " " + constantText(p_.constants[i]);
    if (p_.constants.empty()) out_ += " (none)";
    out_ += "\n";
  }

  void subHeader(const SubInfo& s) {
    sub_ = &s;
    out_ += "\nsub " + s.name + "(";
    for (uint32_t i = 0; i < s.paramCount; ++i) {
      if (i) out_ += ", ";
      if (i < s.byRef.size() && s.byRef[i]) out_ += "&";
      out_ += i < s.slotNames.size() ? s.slotNames[i] : "?";
    }
    out_ += "): entry " + std::to_string(s.entry) + ", frame " + std::to_string(s.frameSize) +
            " (locals";
    for (uint32_t i = 0; i < s.localCount && i < s.slotNames.size(); ++i)
      out_ += (i ? ", " : " ") + s.slotNames[i];
    uint32_t temps = s.frameSize - s.localCount;
    out_ += "; " + std::to_string(temps) + (temps == 1 ? " temporary)" : " temporaries)");
    if (s.outputsFrom < s.paramCount) {
      out_ += "; outputs, not copied in:";
      for (uint32_t i = s.outputsFrom; i < s.paramCount && i < s.slotNames.size(); ++i)
        out_ += " &" + s.slotNames[i];
    }
    if (s.emptyFrom != s.paramCount || s.emptyTo != s.localCount) {
      out_ += "; a call empties";
      if (s.emptyFrom >= s.emptyTo) out_ += " none";
      for (uint32_t i = s.emptyFrom; i < s.emptyTo && i < s.slotNames.size(); ++i) out_ += " " + s.slotNames[i];
    }
    out_ += "\n";
    lastLine_ = SourceLoc{};
  }

  /// "; file:line  text" when the instruction starts a new source line.
  void sourceLine(uint32_t pc) {
    SourceLoc loc = pc < p_.locs.size() ? p_.locs[pc] : SourceLoc{};
    if (!loc.valid() || (loc.file == lastLine_.file && loc.line == lastLine_.line)) return;
    lastLine_ = loc;
    std::string_view text;
    std::string name = "?";
    if (loc.file < sources_.size()) {
      name = sources_.file(loc.file).name();
      text = sources_.file(loc.file).lineText(loc.line);
    }
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
      text.remove_suffix(1);
    size_t slash = name.find_last_of('/');
    if (slash != std::string::npos) name = name.substr(slash + 1);
    out_ += "            ; " + name + ":" + std::to_string(loc.line) + "  " + std::string(text) + "\n";
  }

  void instruction(uint32_t pc) {
    const Instr& in = p_.code[pc];
    char head[40];
    std::snprintf(head, sizeof head, "%6u %c  %-12s ", pc, targets_.count(pc) ? '>' : ' ',
                  opName(in.op));
    std::string line = head;
    line += operands(in);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (isTransfer(in.op) && in.steps != 0) line += "  (steps " + std::to_string(in.steps) + ")";
    if (isConditionalTransfer(in.op) && in.flags != 0)
      line += "  (taken: -" + std::to_string(in.flags) + ")";
    out_ += line + "\n";
  }

  std::string operands(const Instr& in) const {
    switch (in.op) {
      case Op::Move:
        return r(in.a) + ", " + r(in.b) + (in.flags & kMoveMayBeUnassigned ? "  (may be unassigned)" : "");
      case Op::Add: case Op::AddKNum: case Op::AddKInt:
      case Op::AddSelf: case Op::AddKNumSelf: case Op::AddKIntSelf:  // never in compiled code
        return r(in.a) + ", " + r(in.b) + ", " + r(in.c) + (in.flags & kAddLeftDies ? "  (left dies)" : "") +
               (in.flags & kAddRightDies ? "  (right dies)" : "");
      case Op::Sub: case Op::Mul: case Op::Div: case Op::Mod: case Op::Pow:
      case Op::SubKNum: case Op::MulKNum: case Op::SubKInt: case Op::MulKInt: case Op::SubKIntSelf:
      case Op::MulAddSelf:
      case Op::BitAnd: case Op::BitOr: case Op::Shl: case Op::Shr:
      case Op::Eq: case Op::Ne: case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge:
        return r(in.a) + ", " + r(in.b) + ", " + r(in.c);
      case Op::Neg: case Op::Not: case Op::BitNot:
        return r(in.a) + ", " + r(in.b);
      case Op::Inc: case Op::Dec:
        return r(in.a);
      case Op::Jump:
        return "-> " + std::to_string(in.a);
      case Op::JumpIfFalse: case Op::JumpIfTrue:
        return r(in.b) + " -> " + std::to_string(in.a);
      case Op::JumpIfNotEq: case Op::JumpIfNotNe: case Op::JumpIfNotLt: case Op::JumpIfNotLe:
      case Op::JumpIfNotGt: case Op::JumpIfNotGe: case Op::JumpIfEq: case Op::JumpIfNe:
      case Op::JumpIfLt: case Op::JumpIfLe: case Op::JumpIfGt: case Op::JumpIfGe:
        return r(in.b) + ", " + r(in.c) + " -> " + std::to_string(in.a);
      case Op::ForPrep:
        return r(in.a) + " from, " + r(in.b) + " to, " + r(in.b + 1) + " step, exit -> " +
               std::to_string(in.c);
      case Op::ForLoop:
      case Op::ForLoop1:
        return r(in.a) + ", " + r(in.b) + ", " + r(in.b + 1) + ", body -> " + std::to_string(in.c);
      case Op::Gosub:
        return "-> " + std::to_string(in.a) + ", frame +" + std::to_string(in.b);
      case Op::Return:
        return in.c ? r(in.b) : "";
      case Op::CallSub: {
        std::string name = in.a < p_.subs.size() ? p_.subs[in.a].name : "?";
        uint32_t n = in.a < p_.subs.size() ? p_.subs[in.a].paramCount : 0;
        return name + "(" + range(operand(Base::Frame, in.b), n) + ")" + result(in.c);
      }
      case Op::CallBuiltin: {
        std::string name = p_.builtins && in.a < p_.builtins->rows().size()
                               ? std::string(p_.builtins->at(in.a).name)
                               : "builtin " + std::to_string(in.a);
        return name + "(" + range(in.b, in.count) + ")" + result(in.c);
      }
      case Op::IndexGet:
        return r(in.a) + ", " + r(in.b) + "[" + range(in.c, in.count) + "]";
      case Op::IndexSet:
        return r(in.a) + "[" + range(in.c, in.count) + "], " + r(in.b);
      case Op::IndexGet2:
        return r(in.a) + ", " + r(operand(Base::Global, in.count)) + "[" + r(in.b) + ", " + r(in.c) + "]";
      case Op::IndexSet2:
        return r(operand(Base::Global, in.count)) + "[" + r(in.b) + ", " + r(in.c) + "], " + r(in.a);
      case Op::Dim:
        return r(in.a) + "[" + range(in.c, in.count) + "]";
      case Op::DataAppend:
        return r(in.a) + ", " + r(in.b);
      case Op::Print:
        return range(in.b, in.count) + separators(in.c, true);
      case Op::Format:
        return r(in.a) + ", " + range(in.b, in.count) + separators(in.c, false);
      case Op::Input:
        return r(in.a) + (in.c ? ", prompt " + r(in.b) : "");
      case Op::Steps:
      case Op::Line:
      case Op::End:
        return "";
    }
    return "?";
  }

  /// One operand: g3:name (a global slot), f2:name or f5 (a frame slot: named locals of a
  /// sub, unnamed temporaries), k1:value (a constant).
  std::string r(uint32_t op) const {
    if (op == kNoOperand) return "-";
    uint32_t i = operandIndex(op);
    std::string out;
    std::string name;
    switch (operandBase(op)) {
      case Base::Global:
        out = 'g';
        if (i < p_.globalNames.size()) name = p_.globalNames[i];
        break;
      case Base::Frame:
        out = 'f';
        if (sub_ && i < sub_->slotNames.size()) name = sub_->slotNames[i];
        break;
      case Base::Const:
        out = 'k';
        if (i < p_.constants.size()) name = constantText(p_.constants[i]);
        break;
    }
    out += std::to_string(i);
    if (!name.empty()) {
      out += ':';
      out += name;
    }
    return out;
  }

  /// n consecutive operands from `first`: "f3", "f3..f5", or "" for none.
  std::string range(uint32_t first, uint32_t n) const {
    if (n == 0) return "";
    if (n == 1) return r(first);
    return r(first) + ".." + r(first + n - 1);
  }

  /// Where a call's result goes (nowhere for a command or a sub called as a statement).
  std::string result(uint32_t dest) const { return dest == kNoOperand ? "" : " -> " + r(dest); }

  /// The separators written after the items (',' or ';'); a print whose list does not end
  /// with one ends its line.
  std::string separators(uint32_t list, bool print) const {
    if (list >= p_.separatorLists.size()) return "";
    std::string seps;
    bool newline = true;
    for (Tok t : p_.separatorLists[list]) {
      newline = t != Tok::Comma && t != Tok::Semicolon;
      if (!newline) seps += t == Tok::Comma ? ',' : ';';
    }
    std::string out;
    if (!seps.empty()) out += "  separators \"" + seps + "\"";
    if (print && newline) out += "  newline";
    return out;
  }

  static std::string constantText(const Value& v) {
    if (!v.isStr()) return formatValue(v);
    std::string out = "\"";
    for (char c : v.str()) {
      if (c == '"' || c == '\\') {
        out += '\\';
        out += c;
      } else if (static_cast<unsigned char>(c) < 32) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "\\x%02x", static_cast<unsigned char>(c));
        out += hex;
      } else {
        out += c;
      }
    }
    return out + "\"";
  }

  const Program& p_;
  const SourceSet& sources_;
  std::string out_;
  std::map<uint32_t, const SubInfo*> subAt_;
  std::multimap<uint32_t, std::string> labelsAt_;
  std::set<uint32_t> targets_;
  const SubInfo* sub_ = nullptr;  ///< the sub whose body is being written
  SourceLoc lastLine_;
};

}  // namespace

std::string dumpCode(const Program& program, const SourceSet& sources) {
  return Dumper(program, sources).run();
}

}  // namespace rb
