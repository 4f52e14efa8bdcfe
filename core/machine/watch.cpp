#include "machine/watch.h"

#include <cmath>
#include <initializer_list>
#include <limits>

#include "base/checked_math.h"
#include "base/runtime_error.h"
#include "lang/ast_walk.h"
#include "lang/parser.h"
#include "lang/suggest.h"
#include "machine/builtins.h"

namespace rb {

using ast::Expr;
using ast::ExprKind;

struct Watch::Parsed {
  SourceSet sources;  ///< the expression's text, which the tree's names point into
  ast::Arena arena;
  const Expr* root = nullptr;
};

bool isPureBuiltin(std::string_view name) {
  const Builtin* b = standardBuiltins().find(name, BuiltinKind::Function);
  return b && (b->traits & trait::kPure);
}

namespace {

/// The longest string `+` builds in a watch: as in the interpreter.
constexpr size_t kMaxStringLength = 64u << 20;

[[noreturn]] void fail(std::string message) { throw RuntimeError(std::move(message)); }

/// The pieces appended one after another (GCC 12 warns falsely, -Wrestrict, about some chains
/// of `"text" + string`).
std::string join(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (std::string_view p : parts) s.append(p);
  return s;
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

std::string symbol(Tok op) {
  switch (op) {
    case Tok::Plus: return "+";
    case Tok::Minus: return "-";
    case Tok::Star: return "*";
    case Tok::Slash: return "/";
    case Tok::Percent: return "%";
    case Tok::KwMod: return "mod";
    case Tok::Caret: return "^";
    case Tok::Amp: return "&";
    case Tok::Pipe: return "|";
    case Tok::Shl: return "<<";
    case Tok::Shr: return ">>";
    case Tok::Tilde: return "~";
    default: return "not";
  }
}

double finite(double r) {
  if (std::fabs(r) > std::numeric_limits<double>::max()) fail("the result is too large");
  return r;
}

int64_t toInteger(const Value& v) {
  if (v.isInt()) return v.i();
  double d = std::trunc(v.d());
  if (!(d >= -9.2e18 && d <= 9.2e18)) fail("number too large for an integer operation");
  return static_cast<int64_t>(d);
}

bool truth(const Value& v) {
  if (v.isInt()) return v.i() != 0;
  if (v.isNum()) return v.d() != 0;
  fail(join({"a condition must be a number, not ", typeName(v)}));
}

bool isComparison(Tok t) {
  return t == Tok::Assign || t == Tok::EqEq || t == Tok::NotEq || t == Tok::Less ||
         t == Tok::LessEq || t == Tok::Greater || t == Tok::GreaterEq;
}

template <typename T>
bool holds(Tok op, T x, T y) {
  switch (op) {
    case Tok::Assign:
    case Tok::EqEq: return x == y;
    case Tok::NotEq: return x != y;
    case Tok::Less: return x < y;
    case Tok::LessEq: return x <= y;
    case Tok::Greater: return x > y;
    default: return x >= y;
  }
}

/// a `op` b as the interpreter compares: numbers by value, strings byte by byte; a string and
/// a number are never equal and have no order.
bool compare(Tok op, const Value& a, const Value& b) {
  if (a.isInt() && b.isInt()) return holds(op, a.i(), b.i());
  if (a.isNumeric() && b.isNumeric()) return holds(op, a.asDouble(), b.asDouble());
  if (a.isStr() && b.isStr()) return holds(op, a.str().compare(b.str()), 0);
  if (a.isArr() || b.isArr()) fail("cannot compare an array");
  if (op == Tok::Assign || op == Tok::EqEq) return false;
  if (op == Tok::NotEq) return true;
  fail(join({"cannot compare ", typeName(a), " with ", typeName(b)}));
}

/// a `op` b for the arithmetic and bitwise operators, as the interpreter's handlers compute.
Value arithmetic(Tok op, const Value& a, const Value& b) {
  if (op == Tok::Plus && !(a.isNumeric() && b.isNumeric())) {
    if ((a.isStr() || a.isNumeric()) && (b.isStr() || b.isNumeric())) {
      std::string left = formatValue(a), right = formatValue(b);
      if (left.size() + right.size() > kMaxStringLength) fail("string too long");
      left.append(right);
      return Value::string(std::move(left));
    }
    fail(join({"cannot add ", typeName(a), " and ", typeName(b)}));
  }
  if (!a.isNumeric() || !b.isNumeric())
    fail(join({"'", symbol(op), "' needs numbers, not ", typeName(a.isNumeric() ? b : a)}));
  bool ints = a.isInt() && b.isInt();
  switch (op) {
    case Tok::Plus:
    case Tok::Minus:
    case Tok::Star: {
      if (ints) {
        int64_t r;
        bool over = op == Tok::Plus    ? __builtin_add_overflow(a.i(), b.i(), &r)
                    : op == Tok::Minus ? __builtin_sub_overflow(a.i(), b.i(), &r)
                                       : mulOverflows(a.i(), b.i(), &r);
        if (!over) return Value::integer(r);
      }
      double x = a.asDouble(), y = b.asDouble();
      return Value::number(finite(op == Tok::Plus ? x + y : op == Tok::Minus ? x - y : x * y));
    }
    case Tok::Slash:
      if (ints) {
        if (b.i() == 0) fail("division by zero");
        if (b.i() != -1 && a.i() % b.i() == 0) return Value::integer(a.i() / b.i());
        if (b.i() == -1 && a.i() != INT64_MIN) return Value::integer(-a.i());
        return Value::number(static_cast<double>(a.i()) / static_cast<double>(b.i()));
      }
      if (b.asDouble() == 0) fail("division by zero");
      return Value::number(finite(a.asDouble() / b.asDouble()));
    case Tok::Percent:
    case Tok::KwMod:
      if (ints) {
        if (b.i() == 0) fail("division by zero (in %)");
        return Value::integer(b.i() == -1 ? 0 : a.i() % b.i());
      }
      if (b.asDouble() == 0) fail("division by zero (in %)");
      return Value::number(std::fmod(a.asDouble(), b.asDouble()));
    case Tok::Caret: {
      if (ints && b.i() >= 0) {
        int64_t base = a.i(), e = b.i(), r = 1;
        bool over = false;
        while (e > 0 && !over) {
          if (e & 1) over = mulOverflows(r, base, &r);
          e >>= 1;
          if (e > 0 && !over) over = mulOverflows(base, base, &base);
        }
        if (!over) return Value::integer(r);
      }
      double r = std::pow(a.asDouble(), b.asDouble());
      if (std::isnan(r)) fail("the result is not a number");
      if (std::isinf(r)) fail("the result is too large");
      return Value::number(r);
    }
    default: {  // & | << >>
      int64_t x = toInteger(a), y = toInteger(b), r = 0;
      if (op == Tok::Amp) {
        r = x & y;
      } else if (op == Tok::Pipe) {
        r = x | y;
      } else if (op == Tok::Shl) {
        r = y < 0 || y > 63 ? 0 : static_cast<int64_t>(static_cast<uint64_t>(x) << y);
      } else {
        r = y < 0 ? x : y > 63 ? (x < 0 ? -1 : 0) : x >> y;
      }
      return Value::integer(r);
    }
  }
}

class Evaluator {
 public:
  Evaluator(const std::vector<VariableView>& vars, Machine& machine) : vars_(vars), m_(machine) {
    for (const VariableView& v : vars_) inSub_ = inSub_ || v.local;
  }

  Value eval(const Expr* e) {
    switch (e->kind) {
      case ExprKind::Int: return Value::integer(e->ival);
      case ExprKind::Float: return Value::number(e->dval);
      case ExprKind::Str: return Value::string(std::string(e->text));
      case ExprKind::Var: {
        if (const Builtin* c = standardBuiltins().find(e->text, BuiltinKind::Constant))
          return Value::integer(c->constant);
        const Value& v = variable(e->text);
        if (v.isUndef()) fail(join({ast::globalName(e->text), " is not assigned yet"}));
        return v;
      }
      case ExprKind::Index: return element(e);
      case ExprKind::Call: return call(e);
      case ExprKind::Unary: {
        Value a = eval(e->args[0]);
        if (e->op == Tok::Minus) {
          if (a.isInt() && a.i() != INT64_MIN) return Value::integer(-a.i());
          if (a.isNumeric()) return Value::number(-a.asDouble());
          fail(join({"'-' needs a number, not ", typeName(a)}));
        }
        if (!a.isNumeric()) fail(join({"'", symbol(e->op), "' needs a number, not ", typeName(a)}));
        if (e->op == Tok::Tilde) return Value::integer(~toInteger(a));
        return Value::boolean(!truth(a));
      }
      case ExprKind::Binary: {
        Tok op = e->op;
        if (op == Tok::KwAnd || op == Tok::AndAnd)
          return Value::boolean(truth(eval(e->args[0])) && truth(eval(e->args[1])));
        if (op == Tok::KwOr || op == Tok::OrOr)
          return Value::boolean(truth(eval(e->args[0])) || truth(eval(e->args[1])));
        Value a = eval(e->args[0]);
        Value b = eval(e->args[1]);
        if (isComparison(op)) return Value::boolean(compare(op, a, b));
        return arithmetic(op, a, b);
      }
    }
    fail("not an expression");
  }

 private:
  /// The variable a name means where the program stands: in a sub its own names first (a
  /// leading '_' names a global, as in the program), then the globals.
  const Value& variable(std::string_view written) {
    bool global = ast::isGlobalRef(written);
    std::string_view name = ast::globalName(written);
    if (inSub_ && !global)
      for (const VariableView& v : vars_)
        if (v.local && v.name == name) return *v.value;
    for (const VariableView& v : vars_)
      if (!v.local && v.name == name) return *v.value;
    std::vector<std::string_view> known;
    for (const VariableView& v : vars_) known.push_back(v.name);
    std::string message = join({"the program has no variable '", name, "'"});
    std::string hint = closestMatch(name, known, true);
    if (!hint.empty()) message += join({"; did you mean '", hint, "'?"});
    fail(message);
  }

  Value element(const Expr* e) {
    std::string_view name = ast::globalName(e->text);
    const Value& arr = variable(e->text);
    if (arr.isUndef()) fail(join({name, " is not assigned yet"}));
    if (!arr.isArr()) fail(join({"'", name, "' is not an array (it holds ", typeName(arr), ")"}));
    const ArrObj& a = arr.arr();
    size_t n = e->args.size();
    if (a.dims.size() != n)
      fail(join({"array '", name, "' has ", std::to_string(a.dims.size()), " dimension",
                 a.dims.size() == 1 ? "" : "s", " but ", std::to_string(n), " ind",
                 n == 1 ? "ex was" : "ices were", " given"}));
    size_t off = 0;
    for (size_t k = 0; k < n; ++k) {
      Value iv = eval(e->args[k]);
      if (!iv.isNumeric()) fail(join({"array index must be a number, not ", typeName(iv)}));
      int64_t i = toInteger(iv);
      if (i < 0 || i >= a.dims[k]) {
        std::string where = n == 1 ? "" : join({" in dimension ", std::to_string(k + 1)});
        fail(join({"index ", std::to_string(i), " is out of range for '", name, "'", where,
                   " (valid: 0 to ", std::to_string(a.dims[k] - 1), ")"}));
      }
      off = off * static_cast<size_t>(a.dims[k]) + static_cast<size_t>(i);
    }
    const Value& v = a.items[off];
    if (v.isUndef()) fail(join({name, "[...] is not assigned yet"}));
    return v;
  }

  Value call(const Expr* e) {
    const Builtin* b = standardBuiltins().find(e->text, BuiltinKind::Function);
    if (!b && standardBuiltins().findAny(e->text))
      fail(join({"a watch calls only the math and string functions, not ", e->text}));
    if (!b) fail(join({"a watch calls no sub ('", e->text, "' is not a built-in function)"}));
    if (!isPureBuiltin(b->name))
      fail(join({"a watch calls only the math and string functions, not ", b->name, "()"}));
    int n = static_cast<int>(e->args.size());
    if (!b->acceptsCount(n))
      fail(join({"'", b->name, "' takes ", b->arityText(), " argument",
                 b->arityText() == "1" ? "" : "s", ", got ", std::to_string(n)}));
    std::vector<Value> args;
    args.reserve(e->args.size());
    for (const Expr* a : e->args) args.push_back(eval(a));
    Args view(*b, args.data(), n);
    Value r = b->fn(m_, view);
    if (r.isNum() && !std::isfinite(r.d()))
      fail(join({b->name, "(): the result is ", std::isnan(r.d()) ? "not a number" : "too large"}));
    return r;
  }

  const std::vector<VariableView>& vars_;
  Machine& m_;
  bool inSub_ = false;
};

}  // namespace

Watch::Watch(std::string text) : text_(std::move(text)), parsed_(std::make_unique<Parsed>()) {
  uint32_t file = parsed_->sources.add("watch", text_);
  DiagnosticList diags;
  parsed_->root =
      parseExpression(parsed_->sources, file, parsed_->arena, standardBuiltins(), diags);
  if (!parsed_->root) {
    syntaxError_ = "not an expression";
    for (const Diagnostic& d : diags.all())
      if (d.severity == Severity::Error) {
        syntaxError_ = d.message;
        break;
      }
  }
}

Watch::~Watch() = default;
Watch::Watch(Watch&&) noexcept = default;
Watch& Watch::operator=(Watch&&) noexcept = default;

WatchResult Watch::evaluate(const std::vector<VariableView>& variables, Machine& machine) const {
  WatchResult r;
  if (!parsed_->root) {
    r.error = syntaxError_;
    return r;
  }
  try {
    r.value = Evaluator(variables, machine).eval(parsed_->root);
  } catch (const RuntimeError& e) {
    r.error = e.message();
  } catch (const std::bad_alloc&) {
    r.error = "out of memory";
  }
  return r;
}

}  // namespace rb
