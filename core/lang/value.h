#pragma once
// RobotBASIC values are typeless: a slot holds an integer, a double, a string or an array
// (arrays live in variables; they are not first-class in expressions). Integers and doubles are
// kept apart so that integral results print without a decimal point. Strings and arrays are
// reference counted and shared between copies; arrays are never copied implicitly.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/large_memory.h"  // LargeAllocator
#include "base/number.h"  // formatNumber

namespace rb {

/// The heap types come last: isHeap() is one comparison.
enum class VType : uint8_t { Undef, Int, Num, Str, Arr };

class Value;

struct StrObj {
  uint32_t refs = 1;
  std::string s;
};

struct ArrObj {
  uint32_t refs = 1;
  std::vector<int64_t> dims;   ///< extent of each dimension
  /// Row-major. A big array's storage is large memory (base/large_memory.h): `dim` of a
  /// million elements maps its pages at once instead of faulting them in one by one.
  std::vector<Value, LargeAllocator<Value>> items;
};

class Value {
 public:
  Value() : type_(VType::Undef), i_(0) {}
  static Value integer(int64_t v) { Value r; r.type_ = VType::Int; r.i_ = v; return r; }
  static Value number(double v) { Value r; r.type_ = VType::Num; r.d_ = v; return r; }
  static Value boolean(bool b) { return integer(b ? 1 : 0); }
  static Value string(std::string s);
  static Value array(std::vector<int64_t> dims);

  Value(const Value& o) : type_(o.type_), i_(o.i_) { retain(); }
  Value(Value&& o) noexcept : type_(o.type_), i_(o.i_) { o.type_ = VType::Undef; }
  // Copies between numbers (the interpreter's common case) are a plain copy of the two words;
  // only a string or an array on either side takes the reference-counting path.
  Value& operator=(const Value& o) {
    if (!isHeap() && !o.isHeap()) {
      type_ = o.type_;
      i_ = o.i_;
      return *this;
    }
    if (this != &o) {
      o.retainConst();
      release();
      type_ = o.type_;
      i_ = o.i_;
    }
    return *this;
  }
  Value& operator=(Value&& o) noexcept {
    if (this != &o) {
      release();
      type_ = o.type_;
      i_ = o.i_;
      o.type_ = VType::Undef;
    }
    return *this;
  }
  ~Value() { release(); }

  VType type() const { return type_; }
  bool isUndef() const { return type_ == VType::Undef; }
  bool isInt() const { return type_ == VType::Int; }
  bool isNum() const { return type_ == VType::Num; }
  bool isNumeric() const { return static_cast<uint8_t>(static_cast<uint8_t>(type_) - 1) < 2; }  // Int or Num
  bool isStr() const { return type_ == VType::Str; }
  bool isArr() const { return type_ == VType::Arr; }
  bool isHeap() const { return type_ >= VType::Str; }  // Str or Arr

  int64_t i() const { return i_; }
  double d() const { return d_; }
  /// The numeric value as a double (Int or Num only).
  double asDouble() const { return type_ == VType::Int ? static_cast<double>(i_) : d_; }
  const std::string& str() const { return s_->s; }
  /// The string's text to change in place when no other value shares it, else nullptr.
  std::string* uniqueStr() { return type_ == VType::Str && s_->refs == 1 ? &s_->s : nullptr; }
  ArrObj& arr() const { return *a_; }

  // Fast in-place setters used by the interpreter's hot paths. A string or array being replaced
  // is released out of line, so that the new number needs no register that survives a call: a
  // double kept across the possible release went through a general register on its way to
  // memory, which put a transfer on every arithmetic result's path.
  void setInt(int64_t v) {
    if (isHeap()) [[unlikely]] return replaceHeap(v);
    type_ = VType::Int;
    i_ = v;
  }
  void setNum(double v) {
    if (isHeap()) [[unlikely]] return replaceHeap(v);
    type_ = VType::Num;
    d_ = v;
  }
  void clear() { release(); type_ = VType::Undef; i_ = 0; }
  /// Copies a number into a value that holds no string or array (nothing to release).
  void setNumeric(const Value& o) { type_ = o.type_; i_ = o.i_; }

 private:
  // Numbers pass both with one comparison (isHeap).
  void retain() {
    if (isHeap()) {
      if (type_ == VType::Str) ++s_->refs;
      else ++a_->refs;
    }
  }
  void retainConst() const { const_cast<Value*>(this)->retain(); }
  // The last reference frees the object out of line, so that releasing stays a few
  // instructions wherever it is inlined.
  void release() {
    if (isHeap()) {
      if (type_ == VType::Str) {
        if (--s_->refs == 0) freeStr(s_);
      } else if (--a_->refs == 0) {
        freeArr(a_);
      }
    }
  }
  static void freeStr(StrObj* s);
  static void freeArr(ArrObj* a);
  /// setInt and setNum on a value that holds a string or an array.
  void replaceHeap(int64_t v);
  void replaceHeap(double v);

  VType type_;
  union {
    int64_t i_;
    double d_;
    StrObj* s_;
    ArrObj* a_;
  };
};

/// A value as `print` shows it.
std::string formatValue(const Value& v);
/// formatValue's text without a copy: a string's own text, a number's written into `room`
/// (valid while both live).
std::string_view printedForm(const Value& v, char (&room)[kNumberTextSize]);
/// Parses text the way `input` and toNumber() do: the whole text (spaces trimmed) must be a
/// number. Returns false when it is not.
bool parseNumber(std::string_view text, Value& out);

}  // namespace rb
