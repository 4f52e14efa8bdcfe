#include "machine/interpreter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>

#include "base/checked_math.h"
#include "base/runtime_error.h"
#include "lang/builtins.h"
#include "lang/suggest.h"

// The dispatch loop is threaded: each handler jumps straight to the next through a table of
// label addresses (computed goto, a GNU extension), and the arithmetic uses GCC's overflow
// builtins. Both are in GCC and Clang, the compilers rb is built with.
#if !defined(__GNUC__)
#error "rb's interpreter needs GCC or Clang (computed goto, __builtin_*_overflow)"
#endif

/// Keeps rarely taken paths (errors) out of the handlers' code.
#define RB_COLD __attribute__((cold, noinline))
/// For the small helpers the handlers share, so that sharing them costs nothing.
#define RB_ALWAYS_INLINE inline __attribute__((always_inline))

namespace rb {

namespace {

/// The longest string `+` builds.
constexpr size_t kMaxStringLength = 64u << 20;

[[noreturn]] RB_COLD void raise(const char* message) { throw RuntimeError(message); }

/// The interpreter's own form of an instruction whose result replaces its left operand
/// (RB_OPCODES' last group), or `op` itself.
Op selfForm(Op op) {
  switch (op) {
    case Op::Add: return Op::AddSelf;
    case Op::AddKNum: return Op::AddKNumSelf;
    case Op::AddKInt: return Op::AddKIntSelf;
    case Op::SubKInt: return Op::SubKIntSelf;
    default: return op;
  }
}

/// Bytes of work in one statement past which it looks at the run's limits (time, memory) at once.
constexpr size_t kLongWork = 1 << 16;

[[noreturn]] RB_COLD void stringTooLong() {
  throw RuntimeError("string too long (more than " + std::to_string(kMaxStringLength) + " characters)");
}

/// `+` with a string: the printed forms joined. `s = s + x`, where no other value shares s,
/// appends in place, so a string grown a piece at a time costs its length, not its square; so
/// does a temporary's string that the compiler says dies here (`leftDies`), moved into d first.
void concatenate(Value& d, Value& a, const Value& b, bool leftDies) {
  std::string* s = nullptr;  // d's string, when b can be appended to it in place
  if (&d == &a) {
    s = d.uniqueStr();
  } else if (leftDies && &d != &b && a.uniqueStr()) {
    d = std::move(a);  // a temporary no one reads again (kAddLeftDies): its string goes on in d
    s = d.uniqueStr();
  }
  if (s) {
    // (printedForm here, without the copy, measured 10% slower calls through execute()'s layout.)
    std::string formatted;
    const std::string& right = b.isStr() ? b.str() : (formatted = formatValue(b));
    if (s->size() + right.size() > kMaxStringLength) stringTooLong();
    s->append(right);  // also right when b is s itself
    return;
  }
  std::string left = formatValue(a), right = formatValue(b);
  if (left.size() + right.size() > kMaxStringLength) stringTooLong();
  left += right;
  d = Value::string(std::move(left));
}

std::string typeName(const Value& v) {
  switch (v.type()) {
    case VType::Int:
    case VType::Num: return "a number";
    case VType::Str: return "a string";
    case VType::Arr: return "an array";
    case VType::Undef: return "nothing";
  }
  return "a value";
}

const char* opSymbol(Op op) {
  switch (op) {
    case Op::Add: return "+";
    case Op::Sub: return "-";
    case Op::Mul: return "*";
    case Op::Div: return "/";
    case Op::Mod: return "%";
    case Op::Pow: return "^";
    case Op::BitAnd: return "&";
    case Op::BitOr: return "|";
    case Op::Shl: return "<<";
    case Op::Shr: return ">>";
    case Op::Neg: return "-";
    case Op::Not: return "not";
    case Op::BitNot: return "~";
    case Op::Inc: return "++";
    case Op::Dec: return "--";
    default: return "?";
  }
}

int64_t toInteger(const Value& v) {
  if (v.isInt()) return v.i();
  double d = std::trunc(v.d());
  if (!(d >= -9.2e18 && d <= 9.2e18)) raise("number too large for an integer operation");
  return static_cast<int64_t>(d);
}

double checked(double r) {
  if (std::isnan(r)) raise("the result is not a number");
  if (std::isinf(r)) raise("the result is too large");
  return r;
}

/// The result of +, -, * or / on two numbers: never one that is not a number, since every value
/// is finite and division by zero is refused first; only an overflow to infinity is an error.
/// (One comparison where checked() needs two.)
RB_ALWAYS_INLINE bool overflowed(double r) { return std::fabs(r) > std::numeric_limits<double>::max(); }
RB_ALWAYS_INLINE double finite(double r) {
  if (overflowed(r)) [[unlikely]] raise("the result is too large");
  return r;
}

/// x `cmp` y.
template <typename T>
RB_ALWAYS_INLINE bool holds(Cmp cmp, T x, T y) {
  switch (cmp) {
    case Cmp::Eq: return x == y;
    case Cmp::Ne: return x != y;
    case Cmp::Lt: return x < y;
    case Cmp::Le: return x <= y;
    case Cmp::Gt: return x > y;
    case Cmp::Ge: return x >= y;
  }
  return false;
}

}  // namespace

std::string formatItems(const Value* items, uint32_t n, const std::vector<Tok>& seps, bool& newline) {
  std::string out;
  newline = true;
  char room[kNumberTextSize];
  for (uint32_t i = 0; i < n; ++i) {
    std::string_view item = printedForm(items[i], room);
    // One line is one string: many long items cannot join into more (print s;s;s... of a long s).
    if (out.size() + item.size() > kMaxStringLength) [[unlikely]] stringTooLong();
    out += item;
    Tok sep = i < seps.size() ? seps[i] : Tok::Eof;
    if (sep == Tok::Semicolon && i + 1 < n) out += '\t';
    if (i + 1 == n && sep != Tok::Eof) {
      newline = false;
      if (sep == Tok::Semicolon) out += '\t';
    }
  }
  return out;
}

Interpreter::Interpreter(const Program& program, Machine& machine) : prog_(program), m_(machine) {}

std::string Interpreter::slotName(uint32_t op) const {
  uint32_t idx = runIndex(op);
  if (runBase(op) == Base::Global && idx < prog_.globalNames.size()) return prog_.globalNames[idx];
  if (runBase(op) == Base::Frame && sub_ >= 0) {
    const SubInfo& s = prog_.subs[static_cast<size_t>(sub_)];
    if (idx < s.slotNames.size()) return s.slotNames[idx];
  }
  return "";
}

// ---------------------------------------------------------------- errors (cold)

RB_COLD void Interpreter::undefined(uint32_t op) const {
  undefinedOp_ = op;
  std::string name = slotName(op);
  if (name.empty()) throw RuntimeError("a value is missing");
  // Did you mean a variable that has a value (as rb check suggests, now from what ran)?
  std::vector<std::string_view> known;
  for (size_t i = 0; i < prog_.globalNames.size() && i < globals_.size(); ++i)
    if (!globals_[i].isUndef()) known.push_back(prog_.globalNames[i]);
  if (sub_ >= 0) {
    const SubInfo& s = prog_.subs[static_cast<size_t>(sub_)];
    for (size_t i = 0; i < s.slotNames.size() && base_ + i < stack_.size(); ++i)
      if (!stack_[base_ + i].isUndef()) known.push_back(s.slotNames[i]);
  }
  std::string message = "variable '" + name + "' is used before it is given a value";
  std::string hint = closestMatch(name, known, true);
  if (!hint.empty() && hint != name) {
    message += "; did you mean '" + hint + "'?";
    if (editDistance(name, hint, true) == 0) message += " (names are case-sensitive)";
  }
  throw RuntimeError(message);
}

RB_COLD std::vector<Diagnostic> Interpreter::callChain() const {
  std::vector<Diagnostic> notes;
  constexpr size_t kShown = 10;
  for (size_t k = depth_; k-- > 0;) {
    const Frame& f = frames_[k];
    if (notes.size() == kShown) {
      notes.push_back({Severity::Note, SourceLoc{}, "... and " + std::to_string(k + 1) + " calls before"});
      break;
    }
    auto callPc = static_cast<uint32_t>(f.ret - code_.data()) - 1;
    if (callPc >= prog_.locs.size()) continue;
    std::string what = f.sub >= 0 ? "sub '" + prog_.subs[static_cast<size_t>(f.sub)].name + "'" : "the gosub";
    notes.push_back({Severity::Note, prog_.locs[callPc],
                     "in " + what + " called from line " + std::to_string(prog_.locs[callPc].line)});
  }
  return notes;
}

/// The end of every instruction whose operands are not what it needs: an operand without a
/// value is named first ("variable 'x' is used before it is given a value"), then the
/// instruction says what it needs ("'-' needs numbers, not a string").
RB_COLD void Interpreter::operandError(const Instr& in) const {
  const Op op = generalOp(in.op);
  switch (op) {
    case Op::Inc:
    case Op::Dec:
    case Op::ForPrep:
    case Op::ForLoop:
    case Op::ForLoop1: {
      const Value& v = bases_(in.a);
      if (v.isUndef()) undefined(in.a);
      if (op == Op::ForPrep) raise("for loop bounds must be numbers");
      if (op == Op::ForLoop || op == Op::ForLoop1)
        throw RuntimeError("the for loop variable '" + slotName(in.a) + "' no longer holds a number");
      throw RuntimeError(std::string("'") + opSymbol(op) + "' needs a number, not " + typeName(v));
    }
    case Op::Move:
    case Op::Neg:
    case Op::Not:
    case Op::BitNot:
    case Op::JumpIfFalse:
    case Op::JumpIfTrue:
    case Op::IndexSet:
    case Op::IndexSet2:
    case Op::DataAppend: {
      const Value& v = bases_(op == Op::IndexSet2 ? in.a : in.b);
      if (v.isUndef()) undefined(op == Op::IndexSet2 ? in.a : in.b);
      if (op == Op::JumpIfFalse || op == Op::JumpIfTrue)
        throw RuntimeError("a condition must be a number, not " + typeName(v));
      if (op == Op::IndexSet || op == Op::IndexSet2 || op == Op::DataAppend)
        raise("an array cannot be stored in an array element");
      throw RuntimeError(std::string("'") + opSymbol(op) + "' needs a number, not " + typeName(v));
    }
    default: {  // the binary operators and the comparisons: R[b] op R[c]
      const Value& a = bases_(in.b);
      const Value& b = bases_(in.c);
      if (a.isUndef()) undefined(in.b);
      if (b.isUndef()) undefined(in.c);
      if (isCompareValue(op) || isCompareJump(op)) {
        if (a.isArr() || b.isArr()) raise("cannot compare an array");
        throw RuntimeError("cannot compare " + typeName(a) + " with " + typeName(b));
      }
      if (op == Op::Add) throw RuntimeError("cannot add " + typeName(a) + " and " + typeName(b));
      throw RuntimeError(std::string("'") + opSymbol(op) + "' needs numbers, not " +
                         typeName(a.isNumeric() ? b : a));
    }
  }
}

RB_COLD void Interpreter::tooDeep() const {
  throw RuntimeError("too many nested gosub/call (" + std::to_string(limits_.maxCallDepth) +
                     "): runaway recursion?");
}

// ---------------------------------------------------------------- shared by the handlers

/// a `cmp` b: numbers by value (inline), strings byte by byte; a string and a number are never
/// equal and have no order (ordering them is an error).
RB_ALWAYS_INLINE bool Interpreter::compare(Cmp cmp, const Value& a, const Value& b, const Instr& in) const {
  if (a.isInt() && b.isInt()) return holds(cmp, a.i(), b.i());
  if (a.isNumeric() && b.isNumeric()) return holds(cmp, a.asDouble(), b.asDouble());
  return compareOthers(cmp, a, b, in);
}

bool Interpreter::compareOthers(Cmp cmp, const Value& a, const Value& b, const Instr& in) const {
  if (a.isStr() && b.isStr()) {
    int order = a.str().compare(b.str());
    // Comparing long strings is long work for one statement: the limits are looked at now, not
    // only every 65,536 statements.
    if (a.str().size() > kLongWork || b.str().size() > kLongWork) [[unlikely]] m_.checkAlarms();
    return holds(cmp, order, 0);
  }
  if (a.isUndef() || b.isUndef() || a.isArr() || b.isArr()) operandError(in);
  if (cmp == Cmp::Eq) return false;
  if (cmp == Cmp::Ne) return true;
  operandError(in);
}

/// The element R[arrOp][R[idxOp]..] of IndexGet and IndexSet: one in-range integer index into
/// a one-dimensional array here, everything else (several indices, conversions, errors) in
/// elementOffset.
RB_ALWAYS_INLINE Value& Interpreter::element(const OperandBases& B, uint32_t arrOp, uint32_t idxOp,
                                             uint16_t count) {
  Value& arr = B(arrOp);
  const Value& i0 = B(idxOp);
  if (arr.isArr() && count == 1 && i0.isInt()) {
    ArrObj& a = arr.arr();
    if (a.dims.size() == 1 && i0.i() >= 0 && i0.i() < a.dims[0]) return a.items[static_cast<size_t>(i0.i())];
  }
  ArrObj& a = arrayOperand(arrOp).arr();
  if (count == 1 && i0.isUndef()) undefined(idxOp);
  return a.items[elementOffset(a, arrOp, &i0, count)];
}

/// The element G[in.count][R[in.b], R[in.c]] of IndexGet2 and IndexSet2: two in-range integer
/// indices into a two-dimensional array here, everything else in element2Slow.
RB_ALWAYS_INLINE Value& Interpreter::element2(const OperandBases& B, const Instr& in) {
  Value& arr = B.global(in.count);
  const Value& x = B(in.b);
  const Value& y = B(in.c);
  if (arr.isArr() && x.isInt() && y.isInt()) [[likely]] {
    ArrObj& a = arr.arr();
    if (a.dims.size() == 2) [[likely]] {
      // Unsigned comparisons also refuse negative indices.
      auto i = static_cast<uint64_t>(x.i()), j = static_cast<uint64_t>(y.i());
      auto rows = static_cast<uint64_t>(a.dims[0]), cols = static_cast<uint64_t>(a.dims[1]);
      if (i < rows && j < cols) [[likely]] return a.items[i * cols + j];
    }
  }
  return element2Slow(in);
}

/// element2's other cases: the same conversions and errors as IndexGet/IndexSet with two indices.
RB_COLD Value& Interpreter::element2Slow(const Instr& in) {
  uint32_t arrOp = runOperand(operand(Base::Global, in.count));
  ArrObj& a = arrayOperand(arrOp).arr();
  if (bases_(in.b).isUndef()) undefined(in.b);
  if (bases_(in.c).isUndef()) undefined(in.c);
  const Value idx[2] = {bases_(in.b), bases_(in.c)};
  return a.items[elementOffset(a, arrOp, idx, 2)];
}

/// Copies an array element out where the destination or the element is a string or an
/// array: through a copy, since the destination may be the array's own variable.
static RB_COLD void copyElement(Value& d, const Value& e) {
  Value v(e);
  d = std::move(v);
}

/// A for loop's step that is not all integers (or overflows): adds the step to the loop
/// variable as doubles; returns whether the loop goes on.
__attribute__((noinline)) bool Interpreter::forLoopStep(const Instr& in) {
  Value& v = bases_(in.a);
  const Value& limit = bases_(in.b);
  const Value& step = bases_(nextOperand(in.b));
  if (!v.isNumeric()) operandError(in);
  double x = v.asDouble() + step.asDouble();
  v.setNum(x);
  return step.asDouble() > 0 ? x <= limit.asDouble() : x >= limit.asDouble();
}

/// Enters a gosub or a sub call: the new frame, for the caller to fill in field by field (a
/// whole Frame built first went through vector registers); the one place that limits how
/// deep calls nest.
RB_ALWAYS_INLINE Interpreter::Frame& Interpreter::pushFrame() {
  if (depth_ >= depthCap_) [[unlikely]] growFrames();
  return frames_[depth_++];
}

RB_COLD void Interpreter::growFrames() {
  if (depth_ >= limits_.maxCallDepth) tooDeep();
  size_t grown = std::max<size_t>(64, frames_.size() * 2);
  frames_.resize(std::min<size_t>(grown, limits_.maxCallDepth));
  depthCap_ = static_cast<uint32_t>(frames_.size());
}

RB_COLD void Interpreter::growStack(size_t size) {
  size_t grown = stack_.size() * 2;
  stack_.resize(grown > size ? grown : size);
  stackSize_ = stack_.size();
  syncFrame();
}

Value& Interpreter::arrayOperand(uint32_t op) {
  Value& v = bases_(op);
  if (v.isArr()) return v;
  std::string name = slotName(op);
  if (v.isUndef()) throw RuntimeError("array '" + name + "' is used before dim or data creates it");
  throw RuntimeError("'" + name + "' is not an array (it holds " + typeName(v) + ")");
}

size_t Interpreter::elementOffset(ArrObj& a, uint32_t arrOp, const Value* idx, uint32_t n) {
  if (a.dims.size() != n) {
    throw RuntimeError("array '" + slotName(arrOp) + "' has " + std::to_string(a.dims.size()) +
                       " dimension" + (a.dims.size() == 1 ? "" : "s") + " but " +
                       std::to_string(n) + " ind" + (n == 1 ? "ex was" : "ices were") + " given");
  }
  size_t off = 0;
  for (uint32_t k = 0; k < n; ++k) {
    const Value& iv = idx[k];
    if (!iv.isNumeric()) {
      if (iv.isUndef()) raise("array index has no value");
      throw RuntimeError("array index must be a number, not " + typeName(iv));
    }
    int64_t i = toInteger(iv);
    if (i < 0 || i >= a.dims[k]) {
      std::string where = n == 1 ? "" : " in dimension " + std::to_string(k + 1);
      throw RuntimeError("index " + std::to_string(i) + " is out of range for '" + slotName(arrOp) +
                         "'" + where + " (valid: 0 to " + std::to_string(a.dims[k] - 1) + ")");
    }
    off = off * static_cast<size_t>(a.dims[k]) + static_cast<size_t>(i);
  }
  return off;
}

// ---------------------------------------------------------------- a run

RunResult Interpreter::run(const RunLimits& limits) {
  limits_ = limits;
  code_ = prog_.code;
  for (Instr& in : code_) {
    forEachOperandField(in, [](uint32_t& x) { x = runOperand(x); });
    if (prog_.finished && in.a == in.b) in.op = selfForm(in.op);
  }
  if (prog_.finished) fuseMultiplyAdds();
  for (Instr& in : code_) {
    // Jump targets become byte offsets (below kMaxInstructions * 16, checked by the compiler).
    if (hasJumpTarget(in.op)) jumpTargetField(in) *= sizeof(Instr);
    // ForLoop1 gives no statements back when it jumps (below); one that must is left to
    // ForLoop, which reads the step of 1 from its slot.
    if (in.op == Op::ForLoop1 && in.flags != 0) in.op = Op::ForLoop;
  }
  globals_.assign(prog_.globalCount + 1, Value());
  stack_.assign(std::max<size_t>(1024, prog_.mainFrameSize + 16), Value());
  stackSize_ = stack_.size();
  frames_.clear();
  depth_ = depthCap_ = 0;
  subEntries_.clear();
  for (const SubInfo& s : prog_.subs)
    subEntries_.push_back({code_.data() + s.entry, s.emptyFrom, s.emptyTo,
                           s.frameSize + prog_.mainFrameSize + 64});
  base_ = 0;
  sub_ = -1;
  bases_.set(Base::Global, globals_.data());
  bases_.set(Base::Frame, stack_.data());
  bases_.set(Base::Const, const_cast<Value*>(prog_.constants.data()));
  errorPc_ = kNoPc;
  undefinedOp_ = kNoOperand;
  stepsDone_ = 0;
  chunk_ = std::max<int64_t>(1, limits_.checkInterval);
  if (limits_.maxSteps && static_cast<uint64_t>(chunk_) > limits_.maxSteps)
    chunk_ = static_cast<int64_t>(limits_.maxSteps);
  stepsLeft_ = chunk_;
  stopStatus_ = RunStatus::Finished;

  // The host's watchdog raises the machine's alarms once the --timeout has passed or memory
  // goes past --max-memory.
  struct Watchdog {
    Host& host;
    bool armed;
    ~Watchdog() {
      if (armed) host.disarmWatchdog();
    }
  } watchdog{m_.host(), limits_.timeoutSeconds > 0 || limits_.maxMemoryBytes > 0};
  m_.alarms().raised.store(0);
  m_.memoryLimit = limits_.maxMemoryBytes;
  if (watchdog.armed) m_.host().armWatchdog({limits_.timeoutSeconds, limits_.maxMemoryBytes}, m_.alarms());

  RunResult result;
  uint32_t pc = 0;
  try {
    try {
      execute(pc);
    } catch (const DeadlinePassed&) {
      stopStatus_ = RunStatus::Timeout;
    }
    result.status = stopStatus_;
    if (stopStatus_ == RunStatus::StepLimit) {
      result.error = Diagnostic{Severity::Error, prog_.locs[pc],
                                "stopped after " + std::to_string(limits_.maxSteps) +
                                    " steps (the --max-steps limit)"};
    } else if (stopStatus_ == RunStatus::Timeout) {
      char secs[32];
      std::snprintf(secs, sizeof secs, "%g", limits_.timeoutSeconds);
      result.error = Diagnostic{Severity::Error, prog_.locs[pc],
                                std::string("stopped after ") + secs + " seconds (the --timeout limit)"};
    }
  } catch (const RuntimeError& e) {
    if (m_.host().stopRequested()) {
      // The host ended the run inside a call (the user quit while the program waited for
      // input): what the call made of that is not the program's error.
      result.status = RunStatus::Stopped;
    } else {
      result.status = RunStatus::RuntimeError;
      SourceLoc loc = pc < prog_.locs.size() ? prog_.locs[pc] : SourceLoc{};
      if (undefinedOp_ != kNoOperand) loc = variableReadNear(loc, undefinedOp_);
      result.error = Diagnostic{Severity::Error, loc, e.message(), e.code()};
      result.error->notes = callChain();
    }
  } catch (const std::bad_alloc&) {
    result.status = RunStatus::RuntimeError;
    SourceLoc loc = pc < prog_.locs.size() ? prog_.locs[pc] : SourceLoc{};
    result.error = Diagnostic{Severity::Error, loc, "out of memory"};
  }
  // Steps are credited at control transfers, and a loop entered at its condition is debited
  // one in advance (the condition's jump credits it back): an error in that condition on its
  // first test stops the count one below where it started. Never below zero (it wrapped to
  // 2^64-1); the hosts that show a count take the larger of it and the statements they saw begin.
  int64_t counted = static_cast<int64_t>(stepsDone_) + (chunk_ - stepsLeft_);
  // A runtime error stops the run between two transfers, before the statements since the last
  // one were credited: in line-traced code their Line instructions say how many began (a
  // robot that crashes in the program's first statements ran them; untraced code has no mark).
  if (result.status == RunStatus::RuntimeError) counted += statementsBegun(pc);
  result.steps = counted < 0 ? 0 : static_cast<uint64_t>(counted);
  return result;
}

SourceLoc Interpreter::variableReadNear(SourceLoc at, uint32_t op) const {
  SourceLoc best = at;
  uint32_t bestDistance = UINT32_MAX;
  for (const Program::VariableRead& r : prog_.variableReads) {
    if (r.loc.file != at.file || r.loc.line != at.line || runOperand(r.operand) != op) continue;
    const uint32_t distance = r.loc.col > at.col ? r.loc.col - at.col : at.col - r.loc.col;
    if (distance < bestDistance) {
      best = r.loc;
      bestDistance = distance;
    }
  }
  return best;
}

int64_t Interpreter::statementsBegun(uint32_t pc) const {
  if (code_.empty()) return 0;
  int64_t n = 0;
  for (size_t i = std::min<size_t>(pc, code_.size() - 1);; --i) {
    const Op op = code_[i].op;
    if (i != pc && isTransfer(op)) break;
    if (op == Op::Line) ++n;
    if (i == 0) break;
  }
  return n;
}

std::vector<VariableView> Interpreter::variables() const {
  // The compiler names its hidden slots in parentheses ("(for limit)"): they are not shown.
  auto named = [](const std::string& n) { return !n.empty() && n[0] != '('; };
  std::vector<VariableView> out;
  for (size_t i = 0; i < prog_.globalNames.size() && i < globals_.size(); ++i)
    if (named(prog_.globalNames[i])) out.push_back({prog_.globalNames[i], false, &globals_[i]});
  if (sub_ >= 0) {
    const SubInfo& s = prog_.subs[static_cast<size_t>(sub_)];
    for (size_t i = 0; i < s.slotNames.size() && base_ + i < stack_.size(); ++i)
      if (named(s.slotNames[i])) out.push_back({s.slotNames[i], true, &stack_[base_ + i]});
  }
  return out;
}

/// Called when a chunk of steps is used up: checks the step limit, the timeout and the host.
/// Returns false when the run must stop (stopStatus_ says why).
bool Interpreter::checkpoint() {
  stepsDone_ += static_cast<uint64_t>(chunk_ - stepsLeft_);
  if (limits_.maxSteps && stepsDone_ >= limits_.maxSteps) {
    stepsDone_ = limits_.maxSteps;
    chunk_ = stepsLeft_ = 0;
    stopStatus_ = RunStatus::StepLimit;
    return false;
  }
  if (limits_.timeoutSeconds > 0 &&
      ((m_.alarms().now() & RunAlarms::kDeadline) || m_.host().wallSeconds() >= limits_.timeoutSeconds)) {
    chunk_ = stepsLeft_ = 0;
    stopStatus_ = RunStatus::Timeout;
    return false;
  }
  if (!m_.host().poll() || m_.host().stopRequested()) {
    chunk_ = stepsLeft_ = 0;
    stopStatus_ = RunStatus::Stopped;
    return false;
  }
  chunk_ = std::max<int64_t>(1, limits_.checkInterval);
  if (limits_.maxSteps && static_cast<uint64_t>(chunk_) > limits_.maxSteps - stepsDone_)
    chunk_ = static_cast<int64_t>(limits_.maxSteps - stepsDone_);
  stepsLeft_ = chunk_;
  return true;
}

// ---------------------------------------------------------------- handlers outside the loop
//
// Handlers that need locals with destructors live outside the dispatch loop: the threaded
// loop jumps from handler to handler with computed gotos, which skip destructors (GCC) or are
// refused (Clang) when such a local is alive. The loop itself keeps only trivial locals.

/// The returns the dispatch loop leaves to this function: the errors.
RB_COLD void Interpreter::badReturn() {
  if (depth_ == 0) raise("return without gosub or call");
  const Frame& f = frames_[depth_ - 1];
  if (f.sub < 0) raise("return with a value from a gosub (only subs return values)");
  // A sub used as a function returned no value: the error belongs to the call.
  --depth_;
  base_ = f.base;
  sub_ = f.callerSub;
  syncFrame();
  errorPc_ = static_cast<uint32_t>(f.ret - code_.data()) - 1;
  throw RuntimeError("sub '" + prog_.subs[static_cast<size_t>(f.sub)].name +
                     "' returned no value (use return with a value)");
}

/// A Mul (or its K forms) whose product only the next instruction reads, an AddSelf that adds
/// it to a variable (`x = x + i * 0.5`, `c = c + a[i, k] * b[k, j]`), becomes MulAddSelf, which
/// runs both. Not where something jumps to the AddSelf: the product would not be there.
void Interpreter::fuseMultiplyAdds() {
  std::vector<bool> entered(code_.size(), false);  // instructions run other than after the one before
  for (const Instr& in : code_)
    if (uint32_t t = jumpTarget(in); t < entered.size()) entered[t] = true;
  for (const SubInfo& s : prog_.subs)
    if (s.entry < entered.size()) entered[s.entry] = true;
  for (size_t k = 0; k + 1 < code_.size(); ++k) {
    Instr& mul = code_[k];
    const Instr& add = code_[k + 1];
    if ((mul.op == Op::Mul || mul.op == Op::MulKNum || mul.op == Op::MulKInt) && add.op == Op::AddSelf &&
        (add.flags & kAddRightDies) && add.c == mul.a && add.a != mul.a && !entered[k + 1])
      mul.op = Op::MulAddSelf;
  }
}

void Interpreter::doCallBuiltin(const Instr& in, uint32_t pc) {
  const Builtin& b = prog_.builtins->at(in.a);
  m_.setLocation(prog_.locs[pc]);
  Args args(b, &bases_(in.b), in.count);
  Value r = b.fn(m_, args);
  // No number that is infinite or not a number enters the program: every value stays finite,
  // so no later conversion to an integer or a pixel meets one.
  if (r.isNum() && !std::isfinite(r.d())) [[unlikely]]
    throw RuntimeError(std::string(b.name) + "(): the result is " +
                       (std::isnan(r.d()) ? "not a number" : "too large"));
  if (in.c != kNoOperand) bases_(in.c) = std::move(r);
}

void Interpreter::doDim(const Instr& in) {
  std::vector<int64_t> dims;
  uint64_t total = 1;
  for (uint32_t k = 0; k < in.count; ++k) {
    const Value& e = bases_(nextOperand(in.c, k));
    if (!e.isNumeric()) {
      if (e.isUndef()) undefined(nextOperand(in.c, k));
      throw RuntimeError("array size must be a number, not " + typeName(e));
    }
    int64_t n = toInteger(e);
    if (n < 1) throw RuntimeError("array size must be at least 1, not " + std::to_string(n));
    // Checked before multiplying: a product past 2^64 would wrap to a small count while each
    // index is still checked only against its own extent.
    if (static_cast<uint64_t>(n) > kMaxArrayElements / total)
      throw RuntimeError("array '" + slotName(in.a) + "' is too large (more than " +
                         std::to_string(kMaxArrayElements) + " elements)");
    total *= static_cast<uint64_t>(n);
    dims.push_back(n);
  }
  // Memory is counted before it is taken: this array and what the run holds already. What the
  // run holds is asked of the host (it reads the process's memory) only for a big array.
  uint64_t need = total * sizeof(Value);
  bool big = need > kLongWork;
  if (!m_.memoryFits(need)) m_.reserveMemory(need, "array '" + slotName(in.a) + "'");
  bases_(in.a) = Value::array(std::move(dims));
  if (big) m_.checkAlarms();  // making a big array takes time too
}

void Interpreter::doDataAppend(const Instr& in) {
  const Value& v = bases_(in.b);
  if (v.isUndef() || v.isArr()) operandError(in);
  Value& arr = bases_(in.a);
  if (arr.isUndef()) arr = Value::array({0});
  if (!arr.isArr()) throw RuntimeError("data: '" + slotName(in.a) + "' is not an array");
  ArrObj& a = arr.arr();
  if (a.dims.size() != 1) throw RuntimeError("data: '" + slotName(in.a) + "' has more than one dimension");
  if (a.items.size() >= kMaxArrayElements) raise("data: array too large");
  a.items.push_back(v);
  a.dims[0] = static_cast<int64_t>(a.items.size());
  m_.checkAlarms();
}

void Interpreter::doPrint(const Instr& in) {
  bool newline;
  std::string text = formatItems(&bases_(in.b), in.count, prog_.separatorLists[in.c], newline);
  m_.print(text, newline);
}

void Interpreter::doFormat(const Instr& in) {
  bool newline;
  std::string text = formatItems(&bases_(in.b), in.count, prog_.separatorLists[in.c], newline);
  bases_(in.a) = Value::string(std::move(text));
}

void Interpreter::doInput(const Instr& in) {
  std::string prompt;
  if (in.c) prompt = formatValue(bases_(in.b));
  std::string line = m_.input(prompt);
  Value v;
  if (!parseNumber(line, v)) v = Value::string(line);
  bases_(in.a) = std::move(v);
}

// ---------------------------------------------------------------- the dispatch loop
//
// B(x) is the value operand x names. The program counter, the operand bases and the step
// budget live in locals so that they stay in registers; they are written back to members
// before anything that reads them (a checkpoint, a frame change, an exception).

#define COUNT_STEPS(in)               \
  do {                                \
    stepsLeft -= (in).steps;          \
    if (stepsLeft <= 0) {             \
      stepsLeft_ = stepsLeft;         \
      if (!checkpoint()) {            \
        pcOut = PC();                 \
        return;                       \
      }                               \
      stepsLeft = stepsLeft_;         \
    }                                 \
  } while (0)
// A conditional transfer that jumps gives back the statements its fall-through path counted
// before the target (Instr::flags; see isConditionalTransfer).
#define JUMP_TAKEN(in, target) \
  do {                         \
    stepsLeft += (in).flags;   \
    ip = at(target);           \
  } while (0)
#define SYNC_FRAME() B.at[static_cast<uint32_t>(Base::Frame)] = bases_.at[static_cast<uint32_t>(Base::Frame)]
// After a call into the host that may block (a built-in, input, a traced line): a host that
// was asked to end the run (the user quit a live view) has returned at once; stop here.
#define STOP_IF_ASKED()                          \
  do {                                           \
    if (m_.host().stopRequested()) {             \
      stopStatus_ = RunStatus::Stopped;          \
      stepsLeft_ = stepsLeft;                    \
      pcOut = PC();                              \
      return;                                    \
    }                                            \
  } while (0)

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#define CASE(name) op_##name:
#define NEXT goto *kDispatch[static_cast<uint8_t>(ip->op)]
#define PC() static_cast<uint32_t>(ip - code)

// GCC merges the handlers' identical tails (the fetch and jump of NEXT) into one shared
// copy, which puts an extra jump in every handler and makes all of them share one
// indirect-branch prediction; keeping the copies apart is the point of threaded dispatch.
// GCC would also pack a call frame's 4-byte fields into vector registers before storing them
// (the SLP vectorizer), which takes more instructions than storing each, and its global common
// subexpression elimination (as GCC's manual warns for computed gotos) keeps values such as the
// constants' base in registers across every dispatch, which costs two instructions in each.
#if defined(__GNUC__) && !defined(__clang__)
__attribute__((optimize("no-crossjumping", "no-tree-slp-vectorize", "no-gcse")))
#endif
void Interpreter::execute(uint32_t& pcOut) {
  const Instr* code = code_.data();
  const Instr* ip = code + pcOut;  // the instruction running
  // The instruction a jump goes to: its target is a byte offset into the code (run()).
  auto at = [code](uint32_t target) {
    return reinterpret_cast<const Instr*>(reinterpret_cast<const char*>(code) + target);
  };
  int64_t stepsLeft = stepsLeft_;
  OperandBases B = bases_;
  static const void* const kDispatch[] = {
#define RB_OPCODE_LABEL(name) &&op_##name,
      RB_OPCODES(RB_OPCODE_LABEL)
#undef RB_OPCODE_LABEL
  };
  try {
    NEXT;
    CASE(Move) {
      const Instr& in = *ip;
      const Value& s = B(in.b);
      Value& d = B(in.a);
      if (s.isNumeric() && !d.isHeap()) [[likely]] {
        d.setNumeric(s);
      } else {
        if (s.isUndef() && !in.flags) operandError(in);
        d = s;
      }
      ++ip;
      NEXT;
    }
// Add's two common cases, each running straight to its own dispatch so that no path jumps to
// a shared tail: two doubles first, then two integers whose sum fits; else on to `other`.
#define ADD_FAST_PATHS(dest, other)                                  \
  if (!a.isNum()) [[unlikely]] goto other##_ints;                    \
  if (!b.isNum()) [[unlikely]] goto other##_ints;                    \
  dest.setNum(finite(a.d() + b.d()));                                \
  ++ip;                                                              \
  NEXT;                                                              \
  other##_ints:                                                      \
  if (a.isInt() && b.isInt()) [[likely]] {                           \
    int64_t r;                                                       \
    if (!__builtin_add_overflow(a.i(), b.i(), &r)) [[likely]] {      \
      dest.setInt(r);                                                \
      ++ip;                                                          \
      NEXT;                                                          \
    }                                                                \
  }                                                                  \
  goto other
    CASE(Add) {
      const Instr& in = *ip;
      Value& a = B(in.b);
      const Value& b = B(in.c);
      Value& d = B(in.a);
      ADD_FAST_PATHS(d, add_others);
    add_others:
      if (a.isInt() && b.isInt()) {  // an integer overflow
        d.setNum(static_cast<double>(a.i()) + static_cast<double>(b.i()));
        ++ip;
        NEXT;
      }
      if (a.isNumeric() && b.isNumeric()) {
        d.setNum(finite(a.asDouble() + b.asDouble()));
        ++ip;
        NEXT;
      }
      if ((a.isStr() || a.isNumeric()) && (b.isStr() || b.isNumeric())) {
        concatenate(d, a, b, in.flags & kAddLeftDies);
        m_.checkAlarms();
        ++ip;
        NEXT;
      }
      operandError(in);
    }
// - and *: integers while the result fits, else doubles. One handler each (no test of the
// opcode inside).
#define ARITHMETIC(overflows, op)                                                   \
  const Instr& in = *ip;                                                            \
  const Value& a = B(in.b);                                                         \
  const Value& b = B(in.c);                                                         \
  Value& d = B(in.a);                                                               \
  if (a.isInt() && b.isInt()) {                                                     \
    int64_t r;                                                                      \
    if (!overflows(a.i(), b.i(), &r)) d.setInt(r);                                  \
    else d.setNum(static_cast<double>(a.i()) op static_cast<double>(b.i()));        \
  } else if (a.isNumeric() && b.isNumeric()) {                                      \
    d.setNum(finite(a.asDouble() op b.asDouble()));                                 \
  } else {                                                                          \
    operandError(in);                                                               \
  }                                                                                 \
  ++ip;                                                                             \
  NEXT
    CASE(Sub) { ARITHMETIC(__builtin_sub_overflow, -); }
    CASE(Mul) { ARITHMETIC(mulOverflows, *); }
#undef ARITHMETIC
// The same with a constant on the right whose type the compiler knew: only the left operand is
// tested; a string, an empty value or an overflow goes to the general handler.
#define ARITHMETIC_KNUM(op, general)                                  \
  const Instr& in = *ip;                                              \
  const Value& a = B(in.b);                                           \
  double k = B.constant(in.c).d();                                             \
  Value& d = B(in.a);                                                 \
  if (a.isNum()) {                                                    \
    d.setNum(finite(a.d() op k));                                     \
    ++ip;                                                             \
    NEXT;                                                             \
  }                                                                   \
  if (a.isInt()) [[likely]] {                                         \
    d.setNum(finite(static_cast<double>(a.i()) op k));                \
    ++ip;                                                             \
    NEXT;                                                             \
  }                                                                   \
  goto general
#define ARITHMETIC_KINT(overflows, op, general)                       \
  const Instr& in = *ip;                                              \
  const Value& a = B(in.b);                                           \
  int64_t k = B.constant(in.c).i();                                            \
  Value& d = B(in.a);                                                 \
  int64_t r;                                                          \
  if (a.isInt() && !overflows(a.i(), k, &r)) [[likely]] {             \
    d.setInt(r);                                                      \
  } else if (a.isNum()) {                                             \
    d.setNum(finite(a.d() op static_cast<double>(k)));                \
  } else {                                                            \
    goto general;                                                     \
  }                                                                   \
  ++ip;                                                               \
  NEXT
    CASE(AddKNum) { ARITHMETIC_KNUM(+, op_Add); }
    CASE(SubKNum) { ARITHMETIC_KNUM(-, op_Sub); }
    CASE(MulKNum) { ARITHMETIC_KNUM(*, op_Mul); }
    CASE(AddKInt) { ARITHMETIC_KINT(__builtin_add_overflow, +, op_Add); }
    CASE(SubKInt) { ARITHMETIC_KINT(__builtin_sub_overflow, -, op_Sub); }
    CASE(MulKInt) { ARITHMETIC_KINT(mulOverflows, *, op_Mul); }
#undef ARITHMETIC_KNUM
#undef ARITHMETIC_KINT
    // The forms whose result replaces the left operand: the test of that operand's type also
    // says that no string or array is being replaced, so the result is stored as it is.
    CASE(AddSelf) {
      const Instr& in = *ip;
      Value& a = B(in.b);
      const Value& b = B(in.c);
      ADD_FAST_PATHS(a, op_Add);
    }
#undef ADD_FAST_PATHS
    // x = x + R[b] * R[c] for the Mul here and the AddSelf after it (fuseMultiplyAdds): the
    // same operations in the same order as the two would do; any other case, and any error,
    // runs them one after the other (the Mul through the general handler).
    CASE(MulAddSelf) {
      const Instr& in = *ip;
      const Value& b = B(in.b);
      const Value& c = B(in.c);
      Value& x = B(ip[1].a);
      if (x.isNum()) [[likely]] {
        double p;
        if (b.isNum() && c.isNum()) [[likely]] {
          p = b.d() * c.d();
        } else if (b.isInt() && c.isNum()) {
          p = static_cast<double>(b.i()) * c.d();
        } else {
          goto op_Mul;
        }
        double s = x.d() + p;
        if (overflowed(p) || overflowed(s)) [[unlikely]] goto op_Mul;
        x.setNum(s);
        ip += 2;
        NEXT;
      }
      if (x.isInt() && b.isInt() && c.isInt()) {
        int64_t p, s;
        if (!mulOverflows(b.i(), c.i(), &p) && !__builtin_add_overflow(x.i(), p, &s)) [[likely]] {
          x.setInt(s);
          ip += 2;
          NEXT;
        }
      }
      goto op_Mul;
    }
    CASE(AddKNumSelf) {
      const Instr& in = *ip;
      Value& a = B(in.b);
      double k = B.constant(in.c).d();
      if (a.isNum()) [[likely]] {
        a.setNum(finite(a.d() + k));
        ++ip;
        NEXT;
      }
      goto op_AddKNum;
    }
// n = n + 1, n = n - 1: an integer that stays one, else the K form.
#define ARITHMETIC_KINT_SELF(overflows, general)                      \
  const Instr& in = *ip;                                              \
  Value& a = B(in.b);                                                 \
  int64_t k = B.constant(in.c).i();                                   \
  int64_t r;                                                          \
  if (a.isInt() && !overflows(a.i(), k, &r)) [[likely]] {             \
    a.setInt(r);                                                      \
    ++ip;                                                             \
    NEXT;                                                             \
  }                                                                   \
  goto general
    CASE(AddKIntSelf) { ARITHMETIC_KINT_SELF(__builtin_add_overflow, op_AddKInt); }
    CASE(SubKIntSelf) { ARITHMETIC_KINT_SELF(__builtin_sub_overflow, op_SubKInt); }
#undef ARITHMETIC_KINT_SELF
    CASE(Div) {
      const Instr& in = *ip;
      const Value& a = B(in.b);
      const Value& b = B(in.c);
      Value& d = B(in.a);
      if (!a.isNumeric() || !b.isNumeric()) operandError(in);
      if (a.isInt() && b.isInt()) {
        if (b.i() == 0) raise("division by zero");
        if (b.i() != -1 && a.i() % b.i() == 0) {
          d.setInt(a.i() / b.i());
        } else if (b.i() == -1 && a.i() != INT64_MIN) {
          d.setInt(-a.i());
        } else {
          d.setNum(static_cast<double>(a.i()) / static_cast<double>(b.i()));
        }
      } else {
        double y = b.asDouble();
        if (y == 0) raise("division by zero");
        d.setNum(finite(a.asDouble() / y));
      }
      ++ip;
      NEXT;
    }
    CASE(Mod) {
      const Instr& in = *ip;
      const Value& a = B(in.b);
      const Value& b = B(in.c);
      Value& d = B(in.a);
      if (!a.isNumeric() || !b.isNumeric()) operandError(in);
      if (a.isInt() && b.isInt()) {
        if (b.i() == 0) raise("division by zero (in %)");
        d.setInt(b.i() == -1 ? 0 : a.i() % b.i());
      } else {
        double y = b.asDouble();
        if (y == 0) raise("division by zero (in %)");
        d.setNum(std::fmod(a.asDouble(), y));
      }
      ++ip;
      NEXT;
    }
    CASE(Pow) {
      const Instr& in = *ip;
      const Value& a = B(in.b);
      const Value& b = B(in.c);
      Value& d = B(in.a);
      if (!a.isNumeric() || !b.isNumeric()) operandError(in);
      if (a.isInt() && b.isInt() && b.i() >= 0) {
        int64_t base = a.i(), e = b.i(), r = 1;
        bool overflow = false;
        while (e > 0 && !overflow) {
          if (e & 1) overflow = mulOverflows(r, base, &r);
          e >>= 1;
          if (e > 0 && !overflow) overflow = mulOverflows(base, base, &base);
        }
        if (!overflow) {
          d.setInt(r);
          ++ip;
          NEXT;
        }
      }
      d.setNum(checked(std::pow(a.asDouble(), b.asDouble())));
      ++ip;
      NEXT;
    }
    CASE(BitAnd)
    CASE(BitOr)
    CASE(Shl)
    CASE(Shr) {
      const Instr& in = *ip;
      const Value& a = B(in.b);
      const Value& b = B(in.c);
      if (!a.isNumeric() || !b.isNumeric()) operandError(in);
      int64_t x = toInteger(a), y = toInteger(b), r = 0;
      switch (in.op) {
        case Op::BitAnd: r = x & y; break;
        case Op::BitOr: r = x | y; break;
        case Op::Shl: r = y < 0 || y > 63 ? 0 : static_cast<int64_t>(static_cast<uint64_t>(x) << y); break;
        default: r = y < 0 ? x : y > 63 ? (x < 0 ? -1 : 0) : x >> y; break;
      }
      B(in.a).setInt(r);
      ++ip;
      NEXT;
    }
    // The comparisons: one compare() for the value forms and the compare-and-jump forms.
#define COMPARE_VALUE(cmp)                          \
  const Instr& in = *ip;                            \
  bool r = compare(cmp, B(in.b), B(in.c), in);      \
  B(in.a).setInt(r);                                \
  ++ip;                                             \
  NEXT
    CASE(Eq) { COMPARE_VALUE(Cmp::Eq); }
    CASE(Ne) { COMPARE_VALUE(Cmp::Ne); }
    CASE(Lt) { COMPARE_VALUE(Cmp::Lt); }
    CASE(Le) { COMPARE_VALUE(Cmp::Le); }
    CASE(Gt) { COMPARE_VALUE(Cmp::Gt); }
    CASE(Ge) { COMPARE_VALUE(Cmp::Ge); }
#undef COMPARE_VALUE
// One handler per compare-and-jump opcode, each with its comparison known when compiled:
// the JumpIf family jumps when the test holds, the JumpIfNot family when it does not.
#define COMPARE_JUMP(cmp, jumpWhen)                          \
  const Instr& in = *ip;                                     \
  COUNT_STEPS(in);                                           \
  if (compare(cmp, B(in.b), B(in.c), in) == (jumpWhen)) {    \
    JUMP_TAKEN(in, in.a);                                    \
  } else {                                                   \
    ++ip;                                                    \
  }                                                          \
  NEXT
    CASE(JumpIfNotEq) { COMPARE_JUMP(Cmp::Eq, false); }
    CASE(JumpIfNotNe) { COMPARE_JUMP(Cmp::Ne, false); }
    CASE(JumpIfNotLt) { COMPARE_JUMP(Cmp::Lt, false); }
    CASE(JumpIfNotLe) { COMPARE_JUMP(Cmp::Le, false); }
    CASE(JumpIfNotGt) { COMPARE_JUMP(Cmp::Gt, false); }
    CASE(JumpIfNotGe) { COMPARE_JUMP(Cmp::Ge, false); }
    CASE(JumpIfEq) { COMPARE_JUMP(Cmp::Eq, true); }
    CASE(JumpIfNe) { COMPARE_JUMP(Cmp::Ne, true); }
    CASE(JumpIfLt) { COMPARE_JUMP(Cmp::Lt, true); }
    CASE(JumpIfLe) { COMPARE_JUMP(Cmp::Le, true); }
    CASE(JumpIfGt) { COMPARE_JUMP(Cmp::Gt, true); }
    CASE(JumpIfGe) { COMPARE_JUMP(Cmp::Ge, true); }
#undef COMPARE_JUMP
    CASE(Neg) {
      const Instr& in = *ip;
      const Value& a = B(in.b);
      if (a.isInt() && a.i() != INT64_MIN) B(in.a).setInt(-a.i());
      else if (a.isNumeric()) B(in.a).setNum(-a.asDouble());
      else operandError(in);
      ++ip;
      NEXT;
    }
    CASE(Not) {
      const Instr& in = *ip;
      const Value& a = B(in.b);
      bool t = false;
      if (a.isInt()) t = a.i() != 0;
      else if (a.isNum()) t = a.d() != 0;
      else operandError(in);
      B(in.a).setInt(!t);
      ++ip;
      NEXT;
    }
    CASE(BitNot) {
      const Instr& in = *ip;
      const Value& a = B(in.b);
      if (!a.isNumeric()) operandError(in);
      B(in.a).setInt(~toInteger(a));
      ++ip;
      NEXT;
    }
    CASE(Inc)
    CASE(Dec) {
      const Instr& in = *ip;
      Value& a = B(in.a);
      int64_t delta = in.op == Op::Inc ? 1 : -1;
      int64_t r;
      if (a.isInt() && !__builtin_add_overflow(a.i(), delta, &r)) a.setInt(r);
      else if (a.isNumeric()) a.setNum(a.asDouble() + static_cast<double>(delta));
      else operandError(in);
      ++ip;
      NEXT;
    }
    CASE(Jump) {
      const Instr& in = *ip;
      COUNT_STEPS(in);
      ip = at(in.a);
      NEXT;
    }
    CASE(JumpIfFalse)
    CASE(JumpIfTrue) {
      const Instr& in = *ip;
      COUNT_STEPS(in);
      const Value& v = B(in.b);
      bool t = false;
      if (v.isInt()) t = v.i() != 0;
      else if (v.isNum()) t = v.d() != 0;
      else operandError(in);
      if (t == (in.op == Op::JumpIfTrue)) {
        JUMP_TAKEN(in, in.a);
      } else {
        ++ip;
      }
      NEXT;
    }
    CASE(ForPrep) {
      const Instr& in = *ip;
      COUNT_STEPS(in);
      Value& v = B(in.a);
      const Value& limit = B(in.b);
      const Value& step = B(nextOperand(in.b));
      if (!v.isNumeric() || !limit.isNumeric() || !step.isNumeric()) operandError(in);
      if (step.asDouble() == 0) raise("for loop step is zero (the loop would never end)");
      bool enter;
      if (v.isInt() && limit.isInt() && step.isInt())
        enter = step.i() > 0 ? v.i() <= limit.i() : v.i() >= limit.i();
      else
        enter = step.asDouble() > 0 ? v.asDouble() <= limit.asDouble() : v.asDouble() >= limit.asDouble();
      if (enter) {
        ++ip;
      } else {
        JUMP_TAKEN(in, in.c);
      }
      NEXT;
    }
    CASE(ForLoop) {
      const Instr& in = *ip;
      COUNT_STEPS(in);
      Value& v = B(in.a);
      const Value& limit = B(in.b);
      const Value& step = B(nextOperand(in.b));
      int64_t r;
      if (v.isInt() && limit.isInt() && step.isInt() && !__builtin_add_overflow(v.i(), step.i(), &r)) {
        v.setInt(r);
        if (step.i() > 0 ? r <= limit.i() : r >= limit.i()) {
          JUMP_TAKEN(in, in.c);
        } else {
          ++ip;
        }
        NEXT;
      }
      if (forLoopStep(in)) JUMP_TAKEN(in, in.c);
      else ++ip;
      NEXT;
    }
    CASE(ForLoop1) {
      const Instr& in = *ip;
      COUNT_STEPS(in);
      Value& v = B(in.a);
      const Value& limit = B(in.b);
      if (v.isInt() && limit.isInt()) [[likely]] {
        if (v.i() < limit.i()) [[likely]] {  // so v + 1 <= limit, and no overflow
          v.setInt(v.i() + 1);
          ip = at(in.c);  // JUMP_TAKEN without giving steps back: flags is 0 (run())
          NEXT;
        }
        if (v.i() < INT64_MAX) {
          v.setInt(v.i() + 1);
          ++ip;
          NEXT;
        }
      }
      if (forLoopStep(in)) JUMP_TAKEN(in, in.c);
      else ++ip;
      NEXT;
    }
    CASE(Gosub) {
      const Instr& in = *ip;
      COUNT_STEPS(in);
      Frame& f = pushFrame();
      f.ret = ip + 1;
      f.base = base_;
      f.dest = kNoOperand;
      f.sub = -1;
      f.callerSub = sub_;
      base_ += in.b;
      ensureStack(size_t(base_) + prog_.mainFrameSize + 64);
      syncFrame();
      SYNC_FRAME();
      ip = at(in.a);
      NEXT;
    }
    CASE(Return) {
      // From a sub: its value (when it returns one) goes to the caller's destination; from a
      // gosub: no value. Anything else is an error (badReturn).
      const Instr& in = *ip;
      COUNT_STEPS(in);
      if (depth_ == 0) [[unlikely]] badReturn();
      const Frame& f = frames_[depth_ - 1];
      const Value* result = &B(in.b);  // read before the frame changes
      bool fromSub = f.sub >= 0;
      if (fromSub ? (!in.c && f.dest != kNoOperand) : in.c != 0) [[unlikely]] badReturn();
      --depth_;
      base_ = f.base;
      sub_ = f.callerSub;  // a gosub's frame keeps its caller's sub too
      syncFrame();
      SYNC_FRAME();
      ip = f.ret;
      if (fromSub && f.dest != kNoOperand) B(f.dest) = *result;
      NEXT;
    }
    CASE(CallSub) {
      const Instr& in = *ip;
      COUNT_STEPS(in);
      const SubEntry& s = subEntries_[in.a];
      const uint32_t caller = base_;
      const uint32_t newBase = caller + in.b;
      ensureStack(size_t(newBase) + s.stackNeed);
      Frame& f = pushFrame();
      f.ret = ip + 1;
      f.base = caller;
      f.dest = in.c;
      f.sub = static_cast<int32_t>(in.a);
      f.callerSub = sub_;
      base_ = newBase;
      sub_ = static_cast<int32_t>(in.a);
      Value* frame = stack_.data() + newBase;
      if (s.emptyFrom < s.emptyTo) [[unlikely]]
        for (uint32_t i = s.emptyFrom; i < s.emptyTo; ++i) frame[i].clear();
      bases_.set(Base::Frame, frame);
      SYNC_FRAME();
      ip = s.entry;
      NEXT;
    }
    CASE(CallBuiltin) {
      doCallBuiltin(*ip, PC());
      STOP_IF_ASKED();
      if (m_.alarmed()) [[unlikely]] {
        // A slow built-in (drawing, a sensor, a real robot's answer) ran past the --timeout, or
        // memory went past --max-memory: DeadlinePassed or a runtime error at this call.
        stepsLeft_ = stepsLeft;
        m_.raiseAlarm();
      }
      ++ip;
      NEXT;
    }
    CASE(IndexGet) {
      const Instr& in = *ip;
      Value& e = element(B, in.b, in.c, in.count);
      if (in.a != in.b) B(in.a) = e;
      else B(in.a) = Value(e);  // the array's own variable: copy the element before the array goes
      ++ip;
      NEXT;
    }
    CASE(IndexSet) {
      const Instr& in = *ip;
      const Value& v = B(in.b);
      if (v.isUndef() || v.isArr()) operandError(in);
      element(B, in.a, in.c, in.count) = v;
      ++ip;
      NEXT;
    }
    CASE(IndexGet2) {
      const Instr& in = *ip;
      const Value& e = element2(B, in);
      Value& d = B(in.a);
      if (!d.isHeap() && !e.isHeap()) d = e;
      else copyElement(d, e);
      ++ip;
      NEXT;
    }
    CASE(IndexSet2) {
      const Instr& in = *ip;
      const Value& v = B(in.a);
      if (v.isUndef() || v.isArr()) operandError(in);
      element2(B, in) = v;
      ++ip;
      NEXT;
    }
    CASE(Dim) {
      doDim(*ip);
      ++ip;
      NEXT;
    }
    CASE(DataAppend) {
      doDataAppend(*ip);
      ++ip;
      NEXT;
    }
    CASE(Print) {
      doPrint(*ip);
      ++ip;
      NEXT;
    }
    CASE(Format) {
      doFormat(*ip);
      ++ip;
      NEXT;
    }
    CASE(Input) {
      doInput(*ip);
      STOP_IF_ASKED();
      ++ip;
      NEXT;
    }
    CASE(Steps) {
      const Instr& in = *ip;
      COUNT_STEPS(in);
      ++ip;
      NEXT;
    }
    CASE(Line) {
      if (m_.host().wantsLines()) {
        m_.host().onLine(prog_.locs[PC()]);
        STOP_IF_ASKED();
      }
      ++ip;
      NEXT;
    }
    CASE(End) {
      stepsLeft_ = stepsLeft - ip->steps;
      pcOut = PC();
      return;
    }
  } catch (...) {
    pcOut = errorPc_ != kNoPc ? errorPc_ : PC();
    errorPc_ = kNoPc;
    stepsLeft_ = stepsLeft;
    throw;
  }
}

#pragma GCC diagnostic pop

#undef COUNT_STEPS
#undef SYNC_FRAME
#undef JUMP_TAKEN
#undef STOP_IF_ASKED
#undef CASE
#undef NEXT
#undef PC

}  // namespace rb
