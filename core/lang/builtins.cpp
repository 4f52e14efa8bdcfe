#include "lang/builtins.h"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cmath>
#include <stdexcept>

#include "base/runtime_error.h"

namespace rb {

namespace {

// ---- signature parsing

struct SigNode {
  enum Kind { Param, Optional } kind;
  ParamSpec param;
  bool repeats = false;
  std::vector<SigNode> children;
};

bool isNameChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

std::vector<SigNode> parseSignature(std::string_view sig, size_t& pos, std::string_view name) {
  std::vector<SigNode> out;
  while (pos < sig.size()) {
    char c = sig[pos];
    if (c == ' ' || c == ',') {
      ++pos;
    } else if (c == '[') {
      ++pos;
      SigNode n{SigNode::Optional, {}, false, parseSignature(sig, pos, name)};
      if (pos >= sig.size() || sig[pos] != ']')
        throw std::logic_error("builtin signature: missing ] in " + std::string(name));
      ++pos;
      out.push_back(std::move(n));
    } else if (c == ']') {
      return out;
    } else {
      SigNode n{SigNode::Param, {}, false, {}};
      if (c == '&') {
        n.param.out = true;
        ++pos;
      }
      size_t start = pos;
      while (pos < sig.size() && isNameChar(sig[pos])) ++pos;
      n.param.name = sig.substr(start, pos - start);
      if (n.param.name.empty())
        throw std::logic_error("builtin signature: bad character in " + std::string(name));
      if (sig.substr(pos, 3) == "...") {
        n.repeats = true;
        pos += 3;
      }
      out.push_back(std::move(n));
    }
  }
  return out;
}

void expand(const std::vector<SigNode>& seq, size_t i, std::vector<ParamSpec> cur,
            std::vector<std::vector<ParamSpec>>& out, bool& repeats) {
  if (i == seq.size()) {
    out.push_back(std::move(cur));
    return;
  }
  const SigNode& n = seq[i];
  if (n.kind == SigNode::Param) {
    cur.push_back(n.param);
    if (n.repeats) repeats = true;
    expand(seq, i + 1, std::move(cur), out, repeats);
    return;
  }
  // Optional group: with it (longer forms first) and without.
  std::vector<std::vector<ParamSpec>> inner;
  expand(n.children, 0, {}, inner, repeats);
  for (auto& in : inner) {
    std::vector<ParamSpec> with = cur;
    with.insert(with.end(), in.begin(), in.end());
    expand(seq, i + 1, std::move(with), out, repeats);
  }
  expand(seq, i + 1, std::move(cur), out, repeats);
}

/// Fills in a row's arity, parameter forms and print-list flag from its signature.
void derive(Builtin& b) {
  if (b.kind == BuiltinKind::Constant) return;
  size_t pos = 0;
  std::vector<SigNode> seq = parseSignature(b.signature, pos, b.name);
  if (pos != b.signature.size())
    throw std::logic_error("builtin signature: unmatched ] in " + std::string(b.name));
  std::vector<std::vector<ParamSpec>> forms;
  bool repeats = false;
  expand(seq, 0, {}, forms, repeats);
  b.minArgs = INT_MAX;
  b.maxArgs = 0;
  for (const auto& f : forms) {
    int n = static_cast<int>(f.size());
    b.minArgs = std::min(b.minArgs, n);
    b.maxArgs = std::max(b.maxArgs, n);
    if (static_cast<int>(b.forms.size()) <= n) b.forms.resize(static_cast<size_t>(n) + 1);
    if (b.forms[static_cast<size_t>(n)].empty()) b.forms[static_cast<size_t>(n)] = f;
  }
  if (repeats) {
    b.maxArgs = -1;
    const auto& longest = b.forms.back();
    if (!longest.empty() && longest.back().name == "items") b.printList = true;
  }
}

char foldCase(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

const char* kindWord(BuiltinKind k) {
  switch (k) {
    case BuiltinKind::Command: return "command";
    case BuiltinKind::Function: return "function";
    case BuiltinKind::Constant: return "constant";
  }
  return "name";
}

}  // namespace

// ---- Builtin

const ParamSpec& Builtin::param(int n, int i) const {
  static const ParamSpec none{"argument", false};
  if (n >= 0 && static_cast<size_t>(n) < forms.size() && !forms[static_cast<size_t>(n)].empty() &&
      i < static_cast<int>(forms[static_cast<size_t>(n)].size()))
    return forms[static_cast<size_t>(n)][static_cast<size_t>(i)];
  // Beyond the listed forms, the repeated last parameter.
  if (maxArgs < 0 && !forms.empty() && !forms.back().empty()) return forms.back().back();
  return none;
}

std::string Builtin::arityText() const {
  if (maxArgs < 0) return "at least " + std::to_string(minArgs);
  if (minArgs == maxArgs) return std::to_string(minArgs);
  return std::to_string(minArgs) + " to " + std::to_string(maxArgs);
}

std::string Builtin::usage() const {
  std::string out(name);
  if (kind == BuiltinKind::Function) {
    out += '(';
    out += signature;
    out += ')';
  } else if (kind == BuiltinKind::Command && !signature.empty()) {
    out += ' ';
    out += signature;
  }
  return out;
}

// ---- BuiltinTable

namespace {
bool foldedEqual(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  // Bytes equal apart from bit 0x20 first (what equal letters of either case are), then exactly.
  unsigned diff = 0;
  for (size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  if (diff == 0) return true;  // the same bytes
  if (diff & ~0x20u) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (foldCase(a[i]) != foldCase(b[i])) return false;
  return true;
}
}  // namespace

uint32_t BuiltinTable::foldedHash(std::string_view name) {
  // FNV-1a over the bytes with bit 0x20 set: the same for names equal but for ASCII case.
  uint32_t h = 2166136261u ^ static_cast<uint32_t>(name.size());
  for (char c : name) h = (h ^ (static_cast<unsigned char>(c) | 0x20u)) * 16777619u;
  return h ^ (h >> 15);
}

BuiltinTable::Entry& BuiltinTable::entryFor(std::string_view name) {
  size_t mask = slots_.size() - 1;
  for (size_t i = foldedHash(name) & mask;; i = (i + 1) & mask) {
    Slot& slot = slots_[i];
    if (slot.name.empty()) {
      slot.name = name;
      return slot.entry;
    }
    if (foldedEqual(slot.name, name)) return slot.entry;
  }
}

BuiltinTable::BuiltinTable(std::vector<Builtin> rows) : rows_(std::move(rows)) {
  size_t size = 16;
  while (size < rows_.size() * 2) size *= 2;
  slots_.resize(size);
  for (uint32_t i = 0; i < rows_.size(); ++i) {
    Builtin& b = rows_[i];
    derive(b);
    auto k = static_cast<size_t>(b.kind);
    if (b.name.empty()) throw std::logic_error("builtin table: a row without a name");
    uint32_t& row = entryFor(b.name).row[k];
    if (row == kNone) {
      row = i;
      size_t bit = shapeBit(b.name);
      shapes_[bit / 64] |= uint64_t(1) << (bit % 64);
    } else {
      throw std::logic_error("builtin table: " + std::string(b.name) + " appears twice as a " +
                             kindWord(b.kind));
    }
    names_[k].push_back(b.name);
  }
}

size_t BuiltinTable::shapeBit(std::string_view name) {
  if (name.empty()) return 0;
  auto first = static_cast<size_t>(static_cast<unsigned char>(foldCase(name.front())) & 31);
  auto last = static_cast<size_t>(static_cast<unsigned char>(foldCase(name.back())) & 31);
  return (first << 10) | (last << 5) | (name.size() & 31);
}

const BuiltinTable::Entry* BuiltinTable::lookup(std::string_view name) const {
  size_t bit = shapeBit(name);
  if (!(shapes_[bit / 64] >> (bit % 64) & 1)) return nullptr;
  size_t mask = slots_.size() - 1;
  for (size_t i = foldedHash(name) & mask;; i = (i + 1) & mask) {
    const Slot& slot = slots_[i];
    if (slot.name.empty()) return nullptr;
    if (foldedEqual(slot.name, name)) return &slot.entry;
  }
}

const Builtin* BuiltinTable::find(std::string_view name, BuiltinKind kind) const {
  const Entry* e = lookup(name);
  if (!e) return nullptr;
  uint32_t row = e->row[static_cast<size_t>(kind)];
  return row == kNone ? nullptr : &rows_[row];
}

const Builtin* BuiltinTable::findAny(std::string_view name) const {
  const Entry* e = lookup(name);
  if (!e) return nullptr;
  for (BuiltinKind k : {BuiltinKind::Constant, BuiltinKind::Function, BuiltinKind::Command})
    if (uint32_t row = e->row[static_cast<size_t>(k)]; row != kNone) return &rows_[row];
  return nullptr;
}

std::optional<std::string> BuiltinTable::misuse(std::string_view name, NamePlace place) const {
  if (!lookup(name)) return std::nullopt;  // no built-in's name: allowed anywhere
  const Builtin* b = nullptr;
  const char* use = "";
  std::string how;
  switch (place) {
    case NamePlace::Statement:
      if (find(name, BuiltinKind::Command)) return std::nullopt;
      b = findAny(name);
      use = "use '%' as a statement";
      if (b && b->kind == BuiltinKind::Function)
        how = "use its value, as in x = " + std::string(b->name) + "(...)";
      break;
    case NamePlace::Value:
      if (find(name, BuiltinKind::Constant)) return std::nullopt;
      b = findAny(name);
      use = "use '%' as a variable";
      if (b && b->kind == BuiltinKind::Function) how = "write " + std::string(b->name) + "()";
      break;
    case NamePlace::Call:
      if (find(name, BuiltinKind::Function)) return std::nullopt;
      b = findAny(name);
      use = "call '%' as a function";
      if (b && b->kind == BuiltinKind::Command) how = "write it as a statement";
      break;
    case NamePlace::Array:
      b = findAny(name);
      use = "use '%' as an array";
      break;
    case NamePlace::Store:
      b = findAny(name);
      use = "assign to '%'";
      break;
    case NamePlace::Sub:
      // `name(...)` as a statement or in an expression could mean the sub or the built-in;
      // a constant is never called, so a sub may share its name.
      b = find(name, BuiltinKind::Function);
      if (!b) b = find(name, BuiltinKind::Command);
      use = "use '%' as a sub name";
      break;
  }
  if (!b) return std::nullopt;
  std::string message = "cannot ";
  for (const char* p = use; *p; ++p) {
    if (*p == '%') message += name;
    else message += *p;
  }
  message += ": it is a built-in ";
  message += kindWord(b->kind);
  // Where the program names something of its own, which built-in took the name.
  if (place == NamePlace::Store || place == NamePlace::Array || place == NamePlace::Sub)
    message += " (" + b->usage() + ": " + std::string(b->help.substr(0, b->help.find("; "))) + ")";
  if (!how.empty()) message += "; " + how;
  return message;
}

// ---- Args

std::string Args::describe(int i) const {
  std::string what = builtin_.kind == BuiltinKind::Function ? std::string(builtin_.name) + "()"
                                                            : std::string(builtin_.name);
  return "argument " + std::to_string(i + 1) + " (" + std::string(builtin_.param(n_, i).name) +
         ") of " + what;
}

double Args::num(int i) const {
  const Value& v = v_[i];
  if (v.isInt()) return static_cast<double>(v.i());
  if (v.isNum()) {
    // Values are finite (the interpreter refuses infinite results); a host or a test passing an
    // argument directly is held to the same rule.
    if (!std::isfinite(v.d())) throw RuntimeError(describe(i) + " must be a finite number");
    return v.d();
  }
  throw RuntimeError(describe(i) + " must be a number, not " +
                     (v.isStr() ? "a string" : v.isArr() ? "an array" : "nothing"));
}

int64_t Args::integer(int i) const {
  const Value& v = v_[i];
  if (v.isInt()) return v.i();
  double d = std::trunc(num(i));
  if (!(d >= -9.2e18 && d <= 9.2e18)) throw RuntimeError(describe(i) + " is too large");
  return static_cast<int64_t>(d);
}

uint32_t Args::colour(int i) const {
  int64_t c = integer(i);
  if (c < 0 || c > 0xFFFFFF) throw RuntimeError(describe(i) + " must be a colour: 0..15 or an RGB() value");
  return static_cast<uint32_t>(c);
}

double Args::within(int i, double limit) const {
  double v = num(i);
  if (v < -limit || v > limit) {
    char text[64];
    std::snprintf(text, sizeof text, "%g", v);
    char range[32];
    std::snprintf(range, sizeof range, "%.0f", limit);
    throw RuntimeError(describe(i) + " is out of range: " + text + " (allowed: -" + range + " to " + range + ")");
  }
  return v;
}

int Args::coordinate(int i) const {
  double v = std::round(num(i));
  if (v < -1e6) v = -1e6;
  if (v > 1e6) v = 1e6;
  return static_cast<int>(v);
}

const std::string& Args::str(int i) const {
  const Value& v = v_[i];
  if (v.isStr()) return v.str();
  throw RuntimeError(describe(i) + " must be a string, not " +
                     (v.isNumeric() ? "a number" : v.isArr() ? "an array" : "nothing"));
}

}  // namespace rb
