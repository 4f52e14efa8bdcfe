#include "machine/interpreter.h"

#include <cmath>
#include <limits>
#include <new>

#include "lang/builtins.h"
#include "base/runtime_error.h"

namespace rb {

namespace {

/// Statements run between two checks of the limits and of the host (a live view polls here).
constexpr int64_t kCheckInterval = 1 << 16;
/// The largest array rb creates.
constexpr uint64_t kMaxArrayElements = 64u << 20;
/// The longest string `+` builds.
constexpr size_t kMaxStringLength = 64u << 20;

/// `+` with a string: the printed forms joined.
void concatenate(Value& d, const Value& a, const Value& b) {
  std::string left = formatValue(a), right = formatValue(b);
  if (left.size() + right.size() > kMaxStringLength)
    throw RuntimeError("string too long (more than " + std::to_string(kMaxStringLength) + " characters)");
  d = Value::string(left + right);
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
    case Op::BitNot: return "~";
    case Op::Inc: return "++";
    case Op::Dec: return "--";
    default: return "?";
  }
}

int64_t toInteger(const Value& v) {
  if (v.isInt()) return v.i();
  double d = std::trunc(v.d());
  if (!(d >= -9.2e18 && d <= 9.2e18)) throw RuntimeError("number too large for an integer operation");
  return static_cast<int64_t>(d);
}

double checked(double r) {
  if (std::isnan(r)) throw RuntimeError("the result is not a number");
  if (std::isinf(r)) throw RuntimeError("the result is too large");
  return r;
}

}  // namespace

std::string formatItems(const Value* items, uint32_t n, const std::vector<Tok>& seps, bool& newline) {
  std::string out;
  newline = true;
  for (uint32_t i = 0; i < n; ++i) {
    out += formatValue(items[i]);
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
  uint32_t idx = operandIndex(op);
  if (operandBase(op) == Base::Global && idx < prog_.globalNames.size()) return prog_.globalNames[idx];
  if (operandBase(op) == Base::Frame && sub_ >= 0) {
    const SubInfo& s = prog_.subs[static_cast<size_t>(sub_)];
    if (idx < s.slotNames.size()) return s.slotNames[idx];
  }
  return "";
}

void Interpreter::undefined(uint32_t op) const {
  std::string name = slotName(op);
  if (name.empty()) throw RuntimeError("a value is missing");
  throw RuntimeError("variable '" + name + "' is used before it is given a value");
}

void Interpreter::ensureStack(size_t size) {
  if (size <= stack_.size()) return;
  size_t grown = stack_.size() * 2;
  stack_.resize(grown > size ? grown : size);
  bases_[1] = stack_.data() + base_;
}

Value& Interpreter::arrayOperand(uint32_t op) {
  Value& v = bases_[op >> kBaseShift][op & kIndexMask];
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
      if (iv.isUndef()) throw RuntimeError("array index has no value");
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

RunResult Interpreter::run(const RunLimits& limits) {
  limits_ = limits;
  globals_.assign(prog_.globalCount + 1, Value());
  stack_.assign(std::max<size_t>(1024, prog_.mainFrameSize + 16), Value());
  frames_.clear();
  base_ = 0;
  sub_ = -1;
  bases_[0] = globals_.data();
  bases_[1] = stack_.data();
  bases_[2] = const_cast<Value*>(prog_.constants.data());
  stepsDone_ = 0;
  chunk_ = kCheckInterval;
  if (limits_.maxSteps && static_cast<uint64_t>(chunk_) > limits_.maxSteps)
    chunk_ = static_cast<int64_t>(limits_.maxSteps);
  stepsLeft_ = chunk_;
  stopStatus_ = RunStatus::Finished;

  RunResult result;
  uint32_t pc = 0;
  try {
    execute(pc);
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
    result.status = RunStatus::RuntimeError;
    SourceLoc loc = pc < prog_.locs.size() ? prog_.locs[pc] : SourceLoc{};
    result.error = Diagnostic{Severity::Error, loc, e.what()};
  } catch (const std::bad_alloc&) {
    result.status = RunStatus::RuntimeError;
    SourceLoc loc = pc < prog_.locs.size() ? prog_.locs[pc] : SourceLoc{};
    result.error = Diagnostic{Severity::Error, loc, "out of memory"};
  } catch (const StopRun&) {
    result.status = RunStatus::Stopped;  // the host ended the run (the user quit a live view)
  }
  result.steps = stepsDone_ + static_cast<uint64_t>(chunk_ - stepsLeft_);
  return result;
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
bool Interpreter::checkpoint(uint32_t /*pc*/) {
  stepsDone_ += static_cast<uint64_t>(chunk_ - stepsLeft_);
  if (limits_.maxSteps && stepsDone_ >= limits_.maxSteps) {
    stepsDone_ = limits_.maxSteps;
    chunk_ = stepsLeft_ = 0;
    stopStatus_ = RunStatus::StepLimit;
    return false;
  }
  if (limits_.timeoutSeconds > 0 && m_.host().wallSeconds() >= limits_.timeoutSeconds) {
    chunk_ = stepsLeft_ = 0;
    stopStatus_ = RunStatus::Timeout;
    return false;
  }
  if (!m_.host().poll()) {
    chunk_ = stepsLeft_ = 0;
    stopStatus_ = RunStatus::Stopped;
    return false;
  }
  chunk_ = kCheckInterval;
  if (limits_.maxSteps && static_cast<uint64_t>(chunk_) > limits_.maxSteps - stepsDone_)
    chunk_ = static_cast<int64_t>(limits_.maxSteps - stepsDone_);
  stepsLeft_ = chunk_;
  return true;
}

// Handlers that need locals with destructors live outside the dispatch loop: the threaded
// loop jumps from handler to handler with computed gotos, which skip destructors (GCC) or are
// refused (Clang) when such a local is alive. The loop itself keeps only trivial locals.
#define RM(x) (bases_[(x) >> kBaseShift][(x) & kIndexMask])

uint32_t Interpreter::doReturn(const Instr& in) {
  if (frames_.empty()) throw RuntimeError("return without gosub or call");
  Frame f = frames_.back();
  if (f.sub < 0) {
    if (in.c) throw RuntimeError("return with a value from a gosub (only subs return values)");
    frames_.pop_back();
    base_ = f.base;
    bases_[1] = stack_.data() + base_;
    return f.returnPc;
  }
  Value result;
  if (in.c) result = RM(in.b);
  frames_.pop_back();
  base_ = f.base;
  sub_ = f.callerSub;
  bases_[1] = stack_.data() + base_;
  if (f.dest != kNoOperand) {
    if (!in.c) {
      throw ReturnAtCall{f.returnPc - 1, "sub '" + prog_.subs[static_cast<size_t>(f.sub)].name +
                                             "' returned no value (use return with a value)"};
    }
    RM(f.dest) = std::move(result);
  }
  return f.returnPc;
}

void Interpreter::doCallBuiltin(const Instr& in, uint32_t pc) {
  const Builtin& b = builtinTable()[in.a];
  m_.setLocation(prog_.locs[pc]);
  Args args(b, &RM(in.b), in.n);
  Value r = b.fn(m_, args);
  if (in.c != kNoOperand) RM(in.c) = std::move(r);
}

void Interpreter::doDim(const Instr& in) {
  std::vector<int64_t> dims;
  uint64_t total = 1;
  for (uint32_t k = 0; k < in.n; ++k) {
    const Value& e = RM(in.c + k);
    if (!e.isNumeric()) {
      if (e.isUndef()) undefined(in.c + k);
      throw RuntimeError("array size must be a number, not " + typeName(e));
    }
    int64_t n = toInteger(e);
    if (n < 1) throw RuntimeError("array size must be at least 1, not " + std::to_string(n));
    total *= static_cast<uint64_t>(n);
    if (total > kMaxArrayElements)
      throw RuntimeError("array '" + slotName(in.a) + "' is too large (more than " +
                         std::to_string(kMaxArrayElements) + " elements)");
    dims.push_back(n);
  }
  RM(in.a) = Value::array(std::move(dims));
}

void Interpreter::doPrint(const Instr& in) {
  bool newline;
  std::string text = formatItems(&RM(in.b), in.n, prog_.separatorLists[in.c], newline);
  m_.print(text, newline);
}

void Interpreter::doFormat(const Instr& in) {
  bool newline;
  std::string text = formatItems(&RM(in.b), in.n, prog_.separatorLists[in.c], newline);
  RM(in.a) = Value::string(std::move(text));
}

void Interpreter::doInput(const Instr& in) {
  std::string prompt;
  if (in.c) prompt = formatValue(RM(in.b));
  std::string line = m_.input(prompt);
  Value v;
  if (!parseNumber(line, v)) v = Value::string(line);
  RM(in.a) = std::move(v);
}

#undef RM

// The dispatch loop. Operands address one of three bases (globals, the current frame,
// constants); R(x) is the value an operand names. The program counter, the bases and the step
// budget live in locals so that they stay in registers; they are written back to members
// before anything that reads them (a checkpoint, a frame change, an exception).
//
// With GCC and Clang the loop is threaded (each handler jumps straight to the next through a
// table of label addresses, a GNU extension); elsewhere it is a plain switch.
#if defined(__GNUC__)
#define RB_THREADED_DISPATCH 1
#endif

#define R(x) (B[(x) >> kBaseShift][(x) & kIndexMask])
#define COUNT_STEPS(in)                                              \
  do {                                                               \
    stepsLeft -= static_cast<int16_t>((in).n);                       \
    if (stepsLeft <= 0) {                                            \
      stepsLeft_ = stepsLeft;                                        \
      if (!checkpoint(pc)) {                                         \
        pcOut = pc;                                                  \
        return;                                                      \
      }                                                              \
      stepsLeft = stepsLeft_;                                        \
    }                                                                \
  } while (0)
#define SYNC_FRAME() B[1] = bases_[1]

#ifdef RB_THREADED_DISPATCH
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#define CASE(name) op_##name:
#define CASE2(a, b) op_##a: op_##b:
#define NEXT goto *kDispatch[static_cast<uint8_t>(code[pc].op)]
#else
#define CASE(name) case Op::name:
#define CASE2(a, b) case Op::a: case Op::b:
#define NEXT continue
#endif

void Interpreter::execute(uint32_t& pcOut) {
  const Instr* code = prog_.code.data();
  uint32_t pc = pcOut;
  int64_t stepsLeft = stepsLeft_;
  Value* B[3] = {bases_[0], bases_[1], bases_[2]};
#ifdef RB_THREADED_DISPATCH
  static const void* const kDispatch[] = {
#define RB_OPCODE_LABEL(name) &&op_##name,
      RB_OPCODES(RB_OPCODE_LABEL)
#undef RB_OPCODE_LABEL
  };
#endif
  try {
#ifdef RB_THREADED_DISPATCH
  NEXT;
  {
#else
  for (;;) {
    switch (code[pc].op) {
#endif
      CASE(Move) {
        const Instr& in = code[pc];
        const Value& s = R(in.b);
        if (s.isUndef() && !in.flags) undefined(in.b);
        R(in.a) = s;
        ++pc;
        NEXT;
      }
      CASE(Add) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        const Value& b = R(in.c);
        Value& d = R(in.a);
        if (a.isInt() && b.isInt()) {
          int64_t r;
          if (!__builtin_add_overflow(a.i(), b.i(), &r)) d.setInt(r);
          else d.setNum(static_cast<double>(a.i()) + static_cast<double>(b.i()));
        } else if (a.isNumeric() && b.isNumeric()) {
          d.setNum(a.asDouble() + b.asDouble());
        } else if ((a.isStr() || a.isNumeric()) && (b.isStr() || b.isNumeric())) {
          concatenate(d, a, b);
        } else {
          if (a.isUndef()) undefined(in.b);
          if (b.isUndef()) undefined(in.c);
          throw RuntimeError("cannot add " + typeName(a) + " and " + typeName(b));
        }
        ++pc;
        NEXT;
      }
      CASE2(Sub, Mul) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        const Value& b = R(in.c);
        Value& d = R(in.a);
        if (a.isInt() && b.isInt()) {
          int64_t r;
          bool overflow = in.op == Op::Sub ? __builtin_sub_overflow(a.i(), b.i(), &r)
                                           : __builtin_mul_overflow(a.i(), b.i(), &r);
          if (!overflow) d.setInt(r);
          else if (in.op == Op::Sub) d.setNum(static_cast<double>(a.i()) - static_cast<double>(b.i()));
          else d.setNum(static_cast<double>(a.i()) * static_cast<double>(b.i()));
        } else if (a.isNumeric() && b.isNumeric()) {
          d.setNum(in.op == Op::Sub ? a.asDouble() - b.asDouble() : a.asDouble() * b.asDouble());
        } else {
          if (a.isUndef()) undefined(in.b);
          if (b.isUndef()) undefined(in.c);
          throw RuntimeError(std::string("'") + opSymbol(in.op) + "' needs numbers, not " +
                             typeName(a.isNumeric() ? b : a));
        }
        ++pc;
        NEXT;
      }
      CASE(Div) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        const Value& b = R(in.c);
        Value& d = R(in.a);
        if (a.isNumeric() && b.isNumeric()) {
          if (a.isInt() && b.isInt()) {
            if (b.i() == 0) throw RuntimeError("division by zero");
            if (b.i() != -1 && a.i() % b.i() == 0) {
              d.setInt(a.i() / b.i());
            } else if (b.i() == -1 && a.i() != INT64_MIN) {
              d.setInt(-a.i());
            } else {
              d.setNum(static_cast<double>(a.i()) / static_cast<double>(b.i()));
            }
          } else {
            double y = b.asDouble();
            if (y == 0) throw RuntimeError("division by zero");
            d.setNum(checked(a.asDouble() / y));
          }
        } else {
          if (a.isUndef()) undefined(in.b);
          if (b.isUndef()) undefined(in.c);
          throw RuntimeError("'/' needs numbers, not " + typeName(a.isNumeric() ? b : a));
        }
        ++pc;
        NEXT;
      }
      CASE(Mod) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        const Value& b = R(in.c);
        Value& d = R(in.a);
        if (a.isNumeric() && b.isNumeric()) {
          if (a.isInt() && b.isInt()) {
            if (b.i() == 0) throw RuntimeError("division by zero (in %)");
            d.setInt(b.i() == -1 ? 0 : a.i() % b.i());
          } else {
            double y = b.asDouble();
            if (y == 0) throw RuntimeError("division by zero (in %)");
            d.setNum(std::fmod(a.asDouble(), y));
          }
        } else {
          if (a.isUndef()) undefined(in.b);
          if (b.isUndef()) undefined(in.c);
          throw RuntimeError("'%' needs numbers, not " + typeName(a.isNumeric() ? b : a));
        }
        ++pc;
        NEXT;
      }
      CASE(Pow) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        const Value& b = R(in.c);
        Value& d = R(in.a);
        if (!a.isNumeric() || !b.isNumeric()) {
          if (a.isUndef()) undefined(in.b);
          if (b.isUndef()) undefined(in.c);
          throw RuntimeError("'^' needs numbers, not " + typeName(a.isNumeric() ? b : a));
        }
        if (a.isInt() && b.isInt() && b.i() >= 0) {
          int64_t base = a.i(), e = b.i(), r = 1;
          bool overflow = false;
          while (e > 0 && !overflow) {
            if (e & 1) overflow = __builtin_mul_overflow(r, base, &r);
            e >>= 1;
            if (e > 0 && !overflow) overflow = __builtin_mul_overflow(base, base, &base);
          }
          if (!overflow) {
            d.setInt(r);
            ++pc;
            NEXT;
          }
        }
        d.setNum(checked(std::pow(a.asDouble(), b.asDouble())));
        ++pc;
        NEXT;
      }
      CASE(BitAnd)
      CASE(BitOr)
      CASE2(Shl, Shr) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        const Value& b = R(in.c);
        if (!a.isNumeric() || !b.isNumeric()) {
          if (a.isUndef()) undefined(in.b);
          if (b.isUndef()) undefined(in.c);
          throw RuntimeError(std::string("'") + opSymbol(in.op) + "' needs numbers, not " +
                             typeName(a.isNumeric() ? b : a));
        }
        int64_t x = toInteger(a), y = toInteger(b), r = 0;
        switch (in.op) {
          case Op::BitAnd: r = x & y; break;
          case Op::BitOr: r = x | y; break;
          case Op::Shl: r = y < 0 || y > 63 ? 0 : static_cast<int64_t>(static_cast<uint64_t>(x) << y); break;
          default: r = y < 0 ? x : y > 63 ? (x < 0 ? -1 : 0) : x >> y; break;
        }
        R(in.a).setInt(r);
        ++pc;
        NEXT;
      }
      CASE(Eq)
      CASE(Ne)
      CASE(Lt)
      CASE(Le)
      CASE2(Gt, Ge) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        const Value& b = R(in.c);
        int cmp;
        if (a.isInt() && b.isInt()) {
          cmp = a.i() < b.i() ? -1 : a.i() > b.i() ? 1 : 0;
        } else if (a.isNumeric() && b.isNumeric()) {
          double x = a.asDouble(), y = b.asDouble();
          cmp = x < y ? -1 : x > y ? 1 : 0;
        } else if (a.isStr() && b.isStr()) {
          int c = a.str().compare(b.str());
          cmp = c < 0 ? -1 : c > 0 ? 1 : 0;
        } else {
          if (a.isUndef()) undefined(in.b);
          if (b.isUndef()) undefined(in.c);
          if (a.isArr() || b.isArr()) throw RuntimeError("cannot compare an array");
          // A string and a number are never equal, and have no order.
          if (in.op == Op::Eq || in.op == Op::Ne) {
            R(in.a).setInt(in.op == Op::Ne);
            ++pc;
            NEXT;
          }
          throw RuntimeError("cannot compare " + typeName(a) + " with " + typeName(b));
        }
        bool r = false;
        switch (in.op) {
          case Op::Eq: r = cmp == 0; break;
          case Op::Ne: r = cmp != 0; break;
          case Op::Lt: r = cmp < 0; break;
          case Op::Le: r = cmp <= 0; break;
          case Op::Gt: r = cmp > 0; break;
          default: r = cmp >= 0; break;
        }
        R(in.a).setInt(r);
        ++pc;
        NEXT;
      }
      CASE(Neg) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        if (a.isInt() && a.i() != INT64_MIN) R(in.a).setInt(-a.i());
        else if (a.isNumeric()) R(in.a).setNum(-a.asDouble());
        else {
          if (a.isUndef()) undefined(in.b);
          throw RuntimeError("'-' needs a number, not " + typeName(a));
        }
        ++pc;
        NEXT;
      }
      CASE(Not) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        bool t;
        if (a.isInt()) t = a.i() != 0;
        else if (a.isNum()) t = a.d() != 0;
        else {
          if (a.isUndef()) undefined(in.b);
          throw RuntimeError("'not' needs a number, not " + typeName(a));
        }
        R(in.a).setInt(!t);
        ++pc;
        NEXT;
      }
      CASE(BitNot) {
        const Instr& in = code[pc];
        const Value& a = R(in.b);
        if (!a.isNumeric()) {
          if (a.isUndef()) undefined(in.b);
          throw RuntimeError("'~' needs a number, not " + typeName(a));
        }
        R(in.a).setInt(~toInteger(a));
        ++pc;
        NEXT;
      }
      CASE2(Inc, Dec) {
        const Instr& in = code[pc];
        Value& a = R(in.a);
        int64_t delta = in.op == Op::Inc ? 1 : -1;
        int64_t r;
        if (a.isInt() && !__builtin_add_overflow(a.i(), delta, &r)) a.setInt(r);
        else if (a.isNumeric()) a.setNum(a.asDouble() + static_cast<double>(delta));
        else {
          if (a.isUndef()) undefined(in.a);
          throw RuntimeError(std::string("'") + opSymbol(in.op) + "' needs a number, not " + typeName(a));
        }
        ++pc;
        NEXT;
      }
      CASE(Jump) {
        const Instr& in = code[pc];
        COUNT_STEPS(in);
        pc = in.a;
        NEXT;
      }
      CASE2(JumpIfFalse, JumpIfTrue) {
        const Instr& in = code[pc];
        COUNT_STEPS(in);
        const Value& v = R(in.b);
        bool t;
        if (v.isInt()) t = v.i() != 0;
        else if (v.isNum()) t = v.d() != 0;
        else {
          if (v.isUndef()) undefined(in.b);
          throw RuntimeError("a condition must be a number, not " + typeName(v));
        }
        pc = (t == (in.op == Op::JumpIfTrue)) ? in.a : pc + 1;
        NEXT;
      }
      CASE2(JumpIfNotLt, JumpIfNotLe)
      CASE2(JumpIfNotGt, JumpIfNotGe)
      CASE2(JumpIfNotEq, JumpIfNotNe)
      CASE2(JumpIfLt, JumpIfLe)
      CASE2(JumpIfGt, JumpIfGe)
      CASE2(JumpIfEq, JumpIfNe) {
        const Instr& in = code[pc];
        COUNT_STEPS(in);
        const Value& a = R(in.b);
        const Value& b = R(in.c);
        int cmp;
        bool ordered = true;
        if (a.isInt() && b.isInt()) {
          cmp = a.i() < b.i() ? -1 : a.i() > b.i() ? 1 : 0;
        } else if (a.isNumeric() && b.isNumeric()) {
          double x = a.asDouble(), y = b.asDouble();
          cmp = x < y ? -1 : x > y ? 1 : 0;
        } else if (a.isStr() && b.isStr()) {
          int c = a.str().compare(b.str());
          cmp = c < 0 ? -1 : c > 0 ? 1 : 0;
        } else {
          if (a.isUndef()) undefined(in.b);
          if (b.isUndef()) undefined(in.c);
          if (a.isArr() || b.isArr()) throw RuntimeError("cannot compare an array");
          ordered = false;
          cmp = 1;  // a string and a number: unequal, and any ordering test is an error
        }
        bool r;
        switch (in.op) {
          case Op::JumpIfNotEq: case Op::JumpIfEq: r = cmp == 0; break;
          case Op::JumpIfNotNe: case Op::JumpIfNe: r = cmp != 0; break;
          case Op::JumpIfNotLt: case Op::JumpIfLt: r = cmp < 0; break;
          case Op::JumpIfNotLe: case Op::JumpIfLe: r = cmp <= 0; break;
          case Op::JumpIfNotGt: case Op::JumpIfGt: r = cmp > 0; break;
          default: r = cmp >= 0; break;
        }
        bool isEquality = in.op == Op::JumpIfNotEq || in.op == Op::JumpIfEq ||
                          in.op == Op::JumpIfNotNe || in.op == Op::JumpIfNe;
        if (!ordered && !isEquality)
          throw RuntimeError("cannot compare " + typeName(a) + " with " + typeName(b));
        bool jumpWhenTrue = in.op >= Op::JumpIfLt;
        pc = (r == jumpWhenTrue) ? in.a : pc + 1;
        NEXT;
      }
      CASE(ForPrep) {
        const Instr& in = code[pc];
        COUNT_STEPS(in);
        Value& v = R(in.a);
        const Value& limit = R(in.b);
        const Value& step = R(in.b + 1);
        if (!v.isNumeric() || !limit.isNumeric() || !step.isNumeric()) {
          if (v.isUndef()) undefined(in.a);
          throw RuntimeError("for loop bounds must be numbers");
        }
        if (step.asDouble() == 0) throw RuntimeError("for loop step is zero (the loop would never end)");
        bool run;
        if (v.isInt() && limit.isInt() && step.isInt())
          run = step.i() > 0 ? v.i() <= limit.i() : v.i() >= limit.i();
        else
          run = step.asDouble() > 0 ? v.asDouble() <= limit.asDouble() : v.asDouble() >= limit.asDouble();
        pc = run ? pc + 1 : in.c;
        NEXT;
      }
      CASE(ForLoop) {
        const Instr& in = code[pc];
        COUNT_STEPS(in);
        Value& v = R(in.a);
        const Value& limit = R(in.b);
        const Value& step = R(in.b + 1);
        int64_t r;
        if (v.isInt() && limit.isInt() && step.isInt() && !__builtin_add_overflow(v.i(), step.i(), &r)) {
          v.setInt(r);
          pc = (step.i() > 0 ? r <= limit.i() : r >= limit.i()) ? in.c : pc + 1;
          NEXT;
        }
        if (!v.isNumeric()) {
          if (v.isUndef()) undefined(in.a);
          throw RuntimeError("the for loop variable '" + slotName(in.a) + "' no longer holds a number");
        }
        double x = v.asDouble() + step.asDouble();
        v.setNum(x);
        pc = (step.asDouble() > 0 ? x <= limit.asDouble() : x >= limit.asDouble()) ? in.c : pc + 1;
        NEXT;
      }
      CASE(Gosub) {
        const Instr& in = code[pc];
        COUNT_STEPS(in);
        if (frames_.size() >= limits_.maxCallDepth)
          throw RuntimeError("too many nested gosub/call (" + std::to_string(limits_.maxCallDepth) +
                             "): runaway recursion?");
        frames_.push_back({pc + 1, base_, kNoOperand, -1, sub_});
        base_ += in.b;
        ensureStack(size_t(base_) + prog_.mainFrameSize + 64);
        bases_[1] = stack_.data() + base_;
        SYNC_FRAME();
        pc = in.a;
        NEXT;
      }
      CASE(Return) {
        const Instr& in = code[pc];
        COUNT_STEPS(in);
        pc = doReturn(in);
        SYNC_FRAME();
        NEXT;
      }
      CASE(CallSub) {
        const Instr& in = code[pc];
        COUNT_STEPS(in);
        if (frames_.size() >= limits_.maxCallDepth)
          throw RuntimeError("too many nested gosub/call (" + std::to_string(limits_.maxCallDepth) +
                             "): runaway recursion?");
        const SubInfo& s = prog_.subs[in.a];
        uint32_t newBase = base_ + in.b;
        ensureStack(size_t(newBase) + s.frameSize + prog_.mainFrameSize + 64);
        Value* frame = stack_.data() + newBase;
        for (uint32_t i = s.paramCount; i < s.localCount; ++i) frame[i].clear();
        frames_.push_back({pc + 1, base_, in.c, static_cast<int32_t>(in.a), sub_});
        base_ = newBase;
        sub_ = static_cast<int32_t>(in.a);
        bases_[1] = frame;
        SYNC_FRAME();
        pc = s.entry;
        NEXT;
      }
      CASE(CallBuiltin) {
        doCallBuiltin(code[pc], pc);
        ++pc;
        NEXT;
      }
      CASE(IndexGet) {
        const Instr& in = code[pc];
        Value& arr = arrayOperand(in.b);
        ArrObj& a = arr.arr();
        size_t off;
        const Value& i0 = R(in.c);
        if (in.n == 1 && i0.isInt() && a.dims.size() == 1 && i0.i() >= 0 && i0.i() < a.dims[0])
          off = static_cast<size_t>(i0.i());
        else if (in.n == 1 && i0.isUndef())
          undefined(in.c);
        else
          off = elementOffset(a, in.b, &i0, in.n);
        R(in.a) = a.items[off];
        ++pc;
        NEXT;
      }
      CASE(IndexSet) {
        const Instr& in = code[pc];
        const Value& v = R(in.b);
        if (v.isUndef()) undefined(in.b);
        if (v.isArr()) throw RuntimeError("an array cannot be stored in an array element");
        Value& arr = arrayOperand(in.a);
        ArrObj& a = arr.arr();
        size_t off;
        const Value& i0 = R(in.c);
        if (in.n == 1 && i0.isInt() && a.dims.size() == 1 && i0.i() >= 0 && i0.i() < a.dims[0])
          off = static_cast<size_t>(i0.i());
        else if (in.n == 1 && i0.isUndef())
          undefined(in.c);
        else
          off = elementOffset(a, in.a, &i0, in.n);
        a.items[off] = v;
        ++pc;
        NEXT;
      }
      CASE(Dim) {
        doDim(code[pc]);
        ++pc;
        NEXT;
      }
      CASE(DataAppend) {
        const Instr& in = code[pc];
        const Value& v = R(in.b);
        if (v.isUndef()) undefined(in.b);
        if (v.isArr()) throw RuntimeError("an array cannot be stored in an array element");
        Value& arr = R(in.a);
        if (arr.isUndef()) arr = Value::array({0});
        if (!arr.isArr()) throw RuntimeError("data: '" + slotName(in.a) + "' is not an array");
        ArrObj& a = arr.arr();
        if (a.dims.size() != 1) throw RuntimeError("data: '" + slotName(in.a) + "' has more than one dimension");
        if (a.items.size() >= kMaxArrayElements) throw RuntimeError("data: array too large");
        a.items.push_back(v);
        a.dims[0] = static_cast<int64_t>(a.items.size());
        ++pc;
        NEXT;
      }
      CASE(Print) {
        doPrint(code[pc]);
        ++pc;
        NEXT;
      }
      CASE(Format) {
        doFormat(code[pc]);
        ++pc;
        NEXT;
      }
      CASE(Input) {
        doInput(code[pc]);
        ++pc;
        NEXT;
      }
      CASE(Steps) {
        const Instr& in = code[pc];
        COUNT_STEPS(in);
        ++pc;
        NEXT;
      }
      CASE(Line) {
        m_.host().onLine(prog_.locs[pc]);
        ++pc;
        NEXT;
      }
      CASE(End) {
        stepsLeft_ = stepsLeft - static_cast<int16_t>(code[pc].n);
        pcOut = pc;
        return;
      }
#ifdef RB_THREADED_DISPATCH
  }
#else
    }
  }
#endif
  } catch (const ReturnAtCall& r) {
    // A sub used as a function returned no value: the error belongs to the call.
    pcOut = r.pc;
    stepsLeft_ = stepsLeft;
    throw RuntimeError(r.message);
  } catch (...) {
    pcOut = pc;
    stepsLeft_ = stepsLeft;
    throw;
  }
}

#ifdef RB_THREADED_DISPATCH
#pragma GCC diagnostic pop
#endif

#undef R
#undef COUNT_STEPS
#undef SYNC_FRAME
#undef CASE
#undef CASE2
#undef NEXT

}  // namespace rb
