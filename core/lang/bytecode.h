#pragma once
// The flat instruction list the compiler produces and the interpreter runs. Labels are
// addresses, variables are slots, so goto/gosub may enter and leave blocks freely.
//
// Operands are 32-bit: the top two bits select a base (global slots, the current frame, the
// constant pool) and the rest is an index into it. Control transfers (jumps, calls, returns,
// for loops, Steps, End) keep their target in `a` and carry in `steps` the number of statements
// that began since the previous transfer, which is how the interpreter counts steps without an
// instruction per statement; other instructions use the same field as `count`, the number of
// consecutive operands they read.

#include <cstdint>
#include <string>
#include <vector>

#include "base/source.h"
#include "lang/token.h"
#include "lang/value.h"

namespace rb {

class BuiltinTable;

// Every instruction, in one list: the enum and the interpreter's dispatch table both come
// from it. Operand use is given beside each.
#define RB_OPCODES(X)                                                                        \
  /* R[a] = R[b]; an unassigned R[b] is an error naming the variable unless flags has   */  \
  /* kMoveMayBeUnassigned                                                                */  \
  X(Move)                                                                                    \
  /* R[a] = R[b] op R[c] */                                                                  \
  X(Add) X(Sub) X(Mul) X(Div) X(Mod) X(Pow) X(BitAnd) X(BitOr) X(Shl) X(Shr)                 \
  /* R[a] = R[b] op R[c] where R[c] is a constant, a number (KNum) or an integer (KInt):  */  \
  /* the handlers test R[b] only, and leave every other case to Add, Sub or Mul           */  \
  X(AddKNum) X(SubKNum) X(MulKNum) X(AddKInt) X(SubKInt) X(MulKInt)                          \
  /* R[a] = (R[b] cmp R[c]) as 0 or 1; the three compare families list Cmp's order */         \
  X(Eq) X(Ne) X(Lt) X(Le) X(Gt) X(Ge)                                                        \
  /* R[a] = op R[b] */                                                                       \
  X(Neg) X(Not) X(BitNot)                                                                    \
  /* R[a] += 1 / -= 1 in place */                                                            \
  X(Inc) X(Dec)                                                                              \
  /* pc = a */                                                                               \
  X(Jump)                                                                                    \
  /* if (!R[b]) pc = a / if (R[b]) pc = a */                                                 \
  X(JumpIfFalse) X(JumpIfTrue)                                                               \
  /* if (!(R[b] cmp R[c])) pc = a */                                                         \
  X(JumpIfNotEq) X(JumpIfNotNe) X(JumpIfNotLt) X(JumpIfNotLe) X(JumpIfNotGt) X(JumpIfNotGe)  \
  /* if (R[b] cmp R[c]) pc = a */                                                            \
  X(JumpIfEq) X(JumpIfNe) X(JumpIfLt) X(JumpIfLe) X(JumpIfGt) X(JumpIfGe)                    \
  /* for: a = control variable, b = limit (step at b+1), c = exit / body target */           \
  X(ForPrep) X(ForLoop)                                                                      \
  /* ForLoop of a loop whose step is the constant 1 */                                       \
  X(ForLoop1)                                                                                \
  /* push a return address, frame base += b; pc = a */                                      \
  X(Gosub)                                                                                   \
  /* pop the innermost gosub or sub call; b = result operand when c = 1 */                   \
  X(Return)                                                                                  \
  /* call sub a with arguments in frame slots b..; result to operand c (or kNoOperand) */     \
  X(CallSub)                                                                                 \
  /* call built-in a, arguments in R[b]..R[b+count-1], result to operand c (or kNoOperand) */ \
  X(CallBuiltin)                                                                             \
  /* R[a] = R[b][R[c]..R[c+count-1]] */                                                      \
  X(IndexGet)                                                                                \
  /* R[a][R[c]..R[c+count-1]] = R[b] */                                                      \
  X(IndexSet)                                                                                \
  /* two indices into the global array G[count], each index any operand:                */  \
  /* R[a] = G[count][R[b], R[c]] / G[count][R[b], R[c]] = R[a]                          */  \
  X(IndexGet2) X(IndexSet2)                                                                  \
  /* R[a] = new array with the `count` extents R[c].. */                                     \
  X(Dim)                                                                                     \
  /* append R[b] to the 1-D array R[a] (creating it) */                                      \
  X(DataAppend)                                                                              \
  /* print R[b]..R[b+count-1] with separator list c */                                       \
  X(Print)                                                                                   \
  /* R[a] = the items R[b]..R[b+count-1] formatted with separator list c */                  \
  X(Format)                                                                                  \
  /* R[a] = a line typed by the user, prompt R[b] when c = 1 */                              \
  X(Input)                                                                                   \
  /* count `steps` statements (where more than kMaxPending piled up) */                      \
  X(Steps)                                                                                   \
  /* statement boundary, emitted only in line-tracing mode */                                \
  X(Line)                                                                                    \
  /* stop the program (`steps` statements counted) */                                        \
  X(End)                                                                                     \
  /* The interpreter's own forms, never compiled: it makes them in its copy of the code   */  \
  /* from Add, AddKNum, AddKInt and SubKInt whose result replaces their left operand       */  \
  /* (`x = x + y`, `n = n + 1`), where a test of that operand also tells that the result   */  \
  /* replaces a number, and leaves every other case to the general form                    */  \
  X(AddSelf) X(AddKNumSelf) X(AddKIntSelf) X(SubKIntSelf)                                    \
  /* in place of a Mul (or its K forms) R[a] = R[b] * R[c] followed by the AddSelf        */  \
  /* x = x + R[a] whose right operand dies (kAddRightDies): x += R[b] * R[c], both          */  \
  /* instructions at once, without storing the product; any other case runs the two       */  \
  X(MulAddSelf)

enum class Op : uint8_t {
#define RB_OPCODE_ENUM(name) name,
  RB_OPCODES(RB_OPCODE_ENUM)
#undef RB_OPCODE_ENUM
};

/// An opcode's name as RB_OPCODES spells it ("JumpIfNotLt"), for the code dump.
inline const char* opName(Op op) {
  static constexpr const char* kNames[] = {
#define RB_OPCODE_NAME(name) #name,
      RB_OPCODES(RB_OPCODE_NAME)
#undef RB_OPCODE_NAME
  };
  return kNames[static_cast<uint8_t>(op)];
}

/// A comparison, in the order of each compare family of RB_OPCODES (Eq..Ge, JumpIfNotEq..,
/// JumpIfEq..): the offset of an opcode in its family.
enum class Cmp : uint8_t { Eq, Ne, Lt, Le, Gt, Ge };

constexpr bool isCompareValue(Op op) { return op >= Op::Eq && op <= Op::Ge; }
constexpr bool isCompareJump(Op op) { return op >= Op::JumpIfNotEq && op <= Op::JumpIfGe; }
/// The comparison of an opcode of one of the three compare families.
constexpr Cmp compareOf(Op op) {
  auto i = static_cast<uint8_t>(op);
  uint8_t first = static_cast<uint8_t>(isCompareValue(op) ? Op::Eq
                                       : op >= Op::JumpIfEq ? Op::JumpIfEq : Op::JumpIfNotEq);
  return static_cast<Cmp>(i - first);
}

/// The general instruction of a specialized one (AddKNum -> Add), else `op` itself: what errors
/// name, since a specialized handler leaves every case it does not take to the general one.
constexpr Op generalOp(Op op) {
  switch (op) {
    case Op::AddKNum: case Op::AddKInt: case Op::AddSelf: case Op::AddKNumSelf: case Op::AddKIntSelf:
      return Op::Add;
    case Op::SubKNum: case Op::SubKInt: case Op::SubKIntSelf: return Op::Sub;
    case Op::MulKNum: case Op::MulKInt: case Op::MulAddSelf: return Op::Mul;
    default: return op;
  }
}

static_assert(static_cast<int>(Op::MulKNum) - static_cast<int>(Op::AddKNum) == static_cast<int>(Op::Mul) - static_cast<int>(Op::Add) &&
              static_cast<int>(Op::MulKInt) - static_cast<int>(Op::AddKInt) == static_cast<int>(Op::Mul) - static_cast<int>(Op::Add) &&
              static_cast<int>(Op::Sub) - static_cast<int>(Op::Add) == 1,
              "the K forms list Add, Sub and Mul in their order (specializeConstants)");

constexpr uint8_t kMoveMayBeUnassigned = 1;
/// Add (and its K forms): R[b] is a temporary that nothing reads after this instruction, so a
/// string there may be taken over and appended to instead of copied.
constexpr uint8_t kAddLeftDies = 1;
/// Add: R[c] is a temporary that nothing reads after this instruction (an operation's result
/// computed for this `+` alone), so the interpreter may compute it without storing it
/// (MulAddSelf).
constexpr uint8_t kAddRightDies = 2;

struct Instr {
  Op op;
  uint8_t flags = 0;  ///< Move: kMoveMayBeUnassigned; Add: kAddLeftDies, kAddRightDies; conditional transfers:
                      ///< steps given back when taken
  union {
    uint16_t count = 0;  ///< consecutive operands read (arguments, indices, items, extents);
                       ///< IndexGet2/IndexSet2: the array's global slot
    int16_t steps;       ///< control transfers: statements counted since the previous one
  };
  uint32_t a = 0, b = 0, c = 0;
};
static_assert(sizeof(Instr) == 16, "an instruction stays 16 bytes");

/// Instructions that report the statements counted since the previous one (in `steps`).
constexpr bool isTransfer(Op op) {
  switch (op) {
    case Op::Jump: case Op::JumpIfFalse: case Op::JumpIfTrue: case Op::ForPrep:
    case Op::ForLoop: case Op::ForLoop1: case Op::Gosub: case Op::Return: case Op::CallSub: case Op::Steps:
    case Op::End:
      return true;
    default:
      return isCompareJump(op);
  }
}

/// Control transfers that may fall through: they count `steps` on both paths, and when they jump
/// they give back `flags` steps, the statements the fall-through path counted before the target
/// (which the target's next transfer reports again).
constexpr bool isConditionalTransfer(Op op) {
  return op == Op::JumpIfFalse || op == Op::JumpIfTrue || op == Op::ForPrep || op == Op::ForLoop ||
         op == Op::ForLoop1 || isCompareJump(op);
}

constexpr uint32_t kBaseShift = 30;
constexpr uint32_t kIndexMask = (1u << kBaseShift) - 1;
/// Slots of each base a program may use: the interpreter finds slot i at byte offset i * 16
/// computed in 32 bits, which drops the base bits only while i stays below 2^26.
constexpr uint32_t kMaxSlots = 1u << 26;
enum class Base : uint32_t { Global = 0, Frame = 1, Const = 2 };
/// Instructions a program may have: the interpreter finds a jump's target at byte offset
/// target * 16, computed in 32 bits.
constexpr uint32_t kMaxInstructions = 1u << 28;
constexpr uint32_t operand(Base base, uint32_t index) {
  return (static_cast<uint32_t>(base) << kBaseShift) | index;
}
constexpr Base operandBase(uint32_t op) { return static_cast<Base>(op >> kBaseShift); }
constexpr uint32_t operandIndex(uint32_t op) { return op & kIndexMask; }
constexpr uint32_t kNoOperand = 0xffffffffu;

/// Calls f(field) for every field of `in` that holds an operand (a slot of a base, or
/// kNoOperand where an optional one is absent), whether the instruction reads it or writes it:
/// what the interpreter re-encodes for its own copy of the code. The first of a run of
/// consecutive operands (arguments, items, indices, extents) stands for the run.
template <class F>
void forEachOperandField(Instr& in, F f) {
  switch (in.op) {
    case Op::Jump: case Op::Gosub: case Op::Steps: case Op::Line: case Op::End:
      break;
    case Op::Inc: case Op::Dec:
      f(in.a);
      break;
    case Op::JumpIfFalse: case Op::JumpIfTrue: case Op::Print:
      f(in.b);
      break;
    case Op::Move: case Op::Neg: case Op::Not: case Op::BitNot: case Op::ForPrep:
    case Op::ForLoop: case Op::ForLoop1: case Op::DataAppend: case Op::Format: case Op::Input:
      f(in.a);
      f(in.b);
      break;
    case Op::Return:
      f(in.b);  // the result when c is 1
      break;
    case Op::CallSub:  // a: the sub, b: where its frame starts (a number of slots)
      f(in.c);
      break;
    case Op::CallBuiltin:  // a: the built-in
      f(in.b);
      f(in.c);
      break;
    case Op::Dim:
      f(in.a);
      f(in.c);
      break;
    default:
      if (isCompareJump(in.op)) {  // a: the target
        f(in.b);
        f(in.c);
      } else {  // R[a] = R[b] op R[c], IndexGet/IndexSet and their 2-D forms
        f(in.a);
        f(in.b);
        f(in.c);
      }
      break;
  }
}

/// Instructions that hold an address they may go to: the jumps, the for loops and Gosub.
constexpr bool hasJumpTarget(Op op) {
  return op == Op::Jump || op == Op::JumpIfFalse || op == Op::JumpIfTrue || op == Op::Gosub ||
         op == Op::ForPrep || op == Op::ForLoop || op == Op::ForLoop1 || isCompareJump(op);
}
constexpr bool isForLoop(Op op) { return op == Op::ForPrep || op == Op::ForLoop || op == Op::ForLoop1; }
/// The field that holds that address: `c` of the for loops, `a` of the others.
inline uint32_t& jumpTargetField(Instr& in) { return isForLoop(in.op) ? in.c : in.a; }
/// The address an instruction may go to (kNoOperand: it holds none).
inline uint32_t jumpTarget(const Instr& in) {
  if (!hasJumpTarget(in.op)) return kNoOperand;
  return isForLoop(in.op) ? in.c : in.a;
}

/// A `sub` after compilation.
struct SubInfo {
  std::string name;
  SourceLoc loc;
  uint32_t entry = 0;        ///< first instruction of the body
  uint32_t end = 0;          ///< one past the body's last instruction (its final Return)
  uint32_t paramCount = 0;
  uint32_t frameSize = 0;    ///< parameters + locals + temporaries
  uint32_t localCount = 0;   ///< parameters + locals (named slots)
  /// Parameters from this one on are by-reference (&) parameters that the sub gives a value
  /// on every path before it reads them or returns: calls do not copy the caller's variables in,
  /// (see compiler_finish.cpp). paramCount or more when there are none.
  uint32_t outputsFrom = UINT32_MAX;
  /// A call empties slots emptyFrom..emptyTo-1 so that no path sees what an earlier call left
  /// there: all the locals, or, once the finisher has run, those that some path may read
  /// before giving them a value (an output never is).
  uint32_t emptyFrom = 0;
  uint32_t emptyTo = 0;
  std::vector<std::string> slotNames;  ///< names of the named frame slots
  std::vector<bool> byRef;
};

/// A label of the program and the instruction it stands for (for the code dump).
struct LabelEntry {
  std::string name;
  uint32_t pc = 0;
};

/// A compiled program: instructions, their source positions, constants and slot names.
struct Program {
  /// The built-ins CallBuiltin's index refers to (the table the program was compiled against).
  const BuiltinTable* builtins = nullptr;
  std::vector<Instr> code;
  std::vector<SourceLoc> locs;         ///< one per instruction
  std::vector<Value> constants;
  std::vector<std::string> globalNames;
  uint32_t globalCount = 0;
  uint32_t mainFrameSize = 0;          ///< temporaries of code outside subs
  std::vector<SubInfo> subs;
  std::vector<std::vector<Tok>> separatorLists;  ///< for Print/Format
  std::vector<LabelEntry> labels;      ///< in order of name
  /// Where expressions read variables (a name's position and its operand): a runtime error about
  /// a variable with no value points at the name, as rb check's warning does, not at the
  /// operator that read it.
  struct VariableRead {
    SourceLoc loc;
    uint32_t operand = 0;
  };
  std::vector<VariableRead> variableReads;
  bool lineTracing = false;
  /// The finisher ran (compiler_finish.cpp): the interpreter may then make its own forms of
  /// instructions too (RB_OPCODES' last group). Plain code runs as compiled.
  bool finished = false;
};

}  // namespace rb
