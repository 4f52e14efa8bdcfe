// The compiler, chapter "finishing the code": once the whole program is compiled, and only when
// its code is kept to run (not for rb check, nor in line-tracing mode, where the live view shows
// every variable):
//
// - Outputs are not copied in. A by-reference parameter that the sub gives a value on every
//   path before it reads it or returns is an output: the caller's value could never be seen, so
//   calls skip the Move that copies it in (SubInfo::outputsFrom). Only a run of such
//   parameters at the end of the list qualifies. `call Fib(n - 1, a)` with `sub Fib(n, &r)`
//   that sets r on both branches saves an instruction per call.
// - A call empties only the locals that some path may read before giving them a value
//   (SubInfo::emptyFrom..emptyTo): a local the sub always writes first, or an output, may keep
//   what an earlier call left in its slot, since nothing reads it. `sub Work(a, b, c)` whose
//   `x = a + b` and `y = x * c` come first empties nothing.
// - +, - and * with a number constant on the right become their K forms (AddKNum, AddKInt..),
//   whose handlers test only the left operand: `x = x + 0.5`, `n - 1`.
// - A jump to a return, an end or another jump becomes that instruction (with both step
//   counts), which saves an instruction on paths like `if ... r = n else ... endif return`.
//   Only where a --max-steps or --timeout stop is still reported at the same statement.
//
// None changes what a program does: the values it prints, its errors, its step counts.

#include "lang/compiler_internal.h"

namespace rb::compiler {

namespace {

/// Calls read(x) for every operand `in` reads, as it was before the instruction ran. `subs`
/// gives a CallSub's parameter count.
template <class Read>
void forEachRead(const Instr& in, const std::vector<SubInfo>& subs, Read read) {
  auto range = [&](uint32_t first, uint32_t n) {
    for (uint32_t k = 0; k < n; ++k) read(first + k);
  };
  switch (in.op) {
    case Op::Move: case Op::Neg: case Op::Not: case Op::BitNot:
    case Op::JumpIfFalse: case Op::JumpIfTrue:
      read(in.b);
      break;
    case Op::Inc: case Op::Dec:
      read(in.a);
      break;
    case Op::ForPrep: case Op::ForLoop: case Op::ForLoop1:
      read(in.a);
      range(in.b, 2);
      break;
    case Op::Return:
      if (in.c) read(in.b);
      break;
    case Op::CallSub:
      range(operand(Base::Frame, in.b), in.a < subs.size() ? subs[in.a].paramCount : 0);
      break;
    case Op::CallBuiltin: case Op::Print: case Op::Format:
      range(in.b, in.count);
      break;
    case Op::IndexGet:
      read(in.b);
      range(in.c, in.count);
      break;
    case Op::IndexSet:
      read(in.a);
      read(in.b);
      range(in.c, in.count);
      break;
    case Op::IndexGet2:
      read(in.b);
      read(in.c);
      break;
    case Op::IndexSet2:
      read(in.a);
      read(in.b);
      read(in.c);
      break;
    case Op::Dim:
      range(in.c, in.count);
      break;
    case Op::DataAppend:
      read(in.a);
      read(in.b);
      break;
    case Op::Input:
      if (in.c) read(in.b);
      break;
    case Op::Jump: case Op::Gosub: case Op::Steps: case Op::Line: case Op::End:
      break;
    default:  // R[a] = R[b] op R[c], compare-and-jump
      read(in.b);
      read(in.c);
      break;
  }
}

/// The operand an instruction surely gives a value (kNoOperand: none). An instruction that
/// fails ends the run, so a write counts from the instruction on.
uint32_t written(const Instr& in) {
  switch (in.op) {
    case Op::Move: case Op::Neg: case Op::Not: case Op::BitNot: case Op::Inc: case Op::Dec:
    case Op::IndexGet: case Op::IndexGet2: case Op::Dim: case Op::DataAppend: case Op::Format:
    case Op::Input:
      return in.a;
    case Op::CallSub: case Op::CallBuiltin:
      return in.c;
    default:
      if (in.op >= Op::Add && in.op <= Op::Ge) return in.a;
      return kNoOperand;
  }
}

bool fallsThrough(Op op) { return op != Op::Jump && op != Op::Return && op != Op::End; }

}  // namespace

void Compiler::finishCode() {
  if (options_.lineTracing && !options_.finishTraced) return;
  p_.finished = true;
  for (SubInfo& s : p_.subs) s.outputsFrom = outputsFrom(s);
  std::vector<bool> dead(p_.code.size(), false);
  bool any = false;
  for (const CopyIn& c : copyIns_) {
    if (c.param >= p_.subs[c.sub].outputsFrom) {
      dead[c.pc] = true;
      any = true;
    }
  }
  if (any) removeInstructions(dead);
  // After the copies-in of outputs are gone: they read the caller's variables.
  for (SubInfo& s : p_.subs) narrowEmptied(s);
  threadJumps();
  specializeConstants();
}

/// +, - and * with a number constant on the right become AddKNum.. or AddKInt..: the constant's
/// type is known here, so their handlers test only the left operand.
void Compiler::specializeConstants() {
  for (Instr& in : p_.code) {
    if ((in.op != Op::Add && in.op != Op::Sub && in.op != Op::Mul) || operandBase(in.c) != Base::Const)
      continue;
    const Value& k = p_.constants[operandIndex(in.c)];
    auto member = static_cast<uint8_t>(static_cast<uint8_t>(in.op) - static_cast<uint8_t>(Op::Add));
    if (k.isNum()) in.op = static_cast<Op>(static_cast<uint8_t>(Op::AddKNum) + member);
    else if (k.isInt()) in.op = static_cast<Op>(static_cast<uint8_t>(Op::AddKInt) + member);
  }
}

/// The slots first..first+count-1 of `sub`'s frame (count <= 64) that some path through the
/// sub reads before giving them a value, one bit each: a forward "surely given a value"
/// analysis over the sub's code. With `returnReads`, a return reads them all (the call copies
/// by-reference parameters out). Code that leaves the sub's instructions (a gosub, a goto out)
/// makes every slot read.
uint64_t Compiler::readBeforeGiven(const SubInfo& sub, uint32_t first, uint32_t count, bool returnReads) const {
  uint64_t all = count == 64 ? ~uint64_t(0) : (uint64_t(1) << count) - 1;
  if (count == 0) return 0;
  if (count > 64 || sub.end <= sub.entry || sub.end > p_.code.size()) return all;
  auto bit = [&](uint32_t x) -> uint64_t {  // the slot's bit, or 0 for any other operand
    if (operandBase(x) != Base::Frame) return 0;
    uint32_t i = operandIndex(x);
    return i >= first && i - first < count ? uint64_t(1) << (i - first) : 0;
  };
  uint64_t inputs = 0;  // slots some path reads before giving them a value
  std::vector<uint64_t> given(sub.end - sub.entry, 0);
  std::vector<bool> seen(sub.end - sub.entry, false);
  std::vector<uint32_t> work{sub.entry};
  seen[0] = true;
  auto flow = [&](uint32_t to, uint64_t state) {
    if (to < sub.entry || to >= sub.end) {
      inputs = all;
      return;
    }
    uint32_t k = to - sub.entry;
    if (!seen[k]) {
      seen[k] = true;
      given[k] = state;
      work.push_back(to);
    } else if ((given[k] & state) != given[k]) {
      given[k] &= state;
      work.push_back(to);
    }
  };
  while (!work.empty() && inputs != all) {
    uint32_t pc = work.back();
    work.pop_back();
    const Instr& in = p_.code[pc];
    uint64_t state = given[pc - sub.entry];
    if (in.op == Op::Gosub) return all;
    forEachRead(in, p_.subs, [&](uint32_t x) { inputs |= bit(x) & ~state; });
    if (in.op == Op::Return && returnReads) inputs |= all & ~state;
    state |= bit(written(in));
    if (uint32_t t = jumpTarget(in); t != kNoOperand) flow(t, state);
    if (fallsThrough(in.op)) flow(pc + 1, state);
  }
  return inputs;
}

/// The first of the by-reference parameters at the end of `sub`'s list that the sub gives a
/// value on every path before reading it or returning (paramCount: none).
uint32_t Compiler::outputsFrom(const SubInfo& sub) const {
  uint32_t first = sub.paramCount;
  while (first > 0 && sub.byRef[first - 1] && sub.paramCount - (first - 1) <= 64) --first;
  if (first == sub.paramCount) return sub.paramCount;
  uint64_t inputs = readBeforeGiven(sub, first, sub.paramCount - first, true);
  // The outputs are the parameters after the last input.
  uint32_t from = sub.paramCount;
  while (from > first && !(inputs & (uint64_t(1) << (from - 1 - first)))) --from;
  return from;
}

/// Narrows the slots a call of `sub` empties (SubInfo::emptyFrom..emptyTo) to the locals that
/// some path may read before giving them a value: a slot the sub always writes first can keep
/// what an earlier call left there, since nothing sees it. Outputs are never read first.
void Compiler::narrowEmptied(SubInfo& sub) const {
  uint32_t from = sub.paramCount, to = sub.localCount;
  if (to <= from) {
    sub.emptyFrom = sub.emptyTo = from;
    return;
  }
  if (to - from > 64) {
    sub.emptyFrom = from;
    sub.emptyTo = to;
    return;
  }
  uint64_t inputs = readBeforeGiven(sub, from, to - from, false);
  if (inputs == 0) {
    sub.emptyFrom = sub.emptyTo = from;
    return;
  }
  sub.emptyFrom = from + static_cast<uint32_t>(__builtin_ctzll(inputs));
  sub.emptyTo = from + 64 - static_cast<uint32_t>(__builtin_clzll(inputs));
}

/// Removes the instructions marked dead, moving every address (jump targets, sub entries and
/// ends, labels) to the instruction that took its place.
void Compiler::removeInstructions(const std::vector<bool>& dead) {
  size_t n = p_.code.size();
  std::vector<uint32_t> moved(n + 1);
  uint32_t next = 0;
  for (size_t pc = 0; pc < n; ++pc) {
    moved[pc] = next;
    if (!dead[pc]) {
      p_.code[next] = p_.code[pc];
      p_.locs[next] = p_.locs[pc];
      ++next;
    }
  }
  moved[n] = next;
  p_.code.resize(next);
  p_.locs.resize(next);
  for (Instr& in : p_.code)
    if (hasJumpTarget(in.op)) jumpTargetField(in) = moved[jumpTargetField(in)];
  for (SubInfo& s : p_.subs) {
    s.entry = moved[s.entry];
    s.end = moved[s.end];
  }
  for (LabelEntry& l : p_.labels) l.pc = moved[l.pc];
  codeSize_ = next;
}

/// Replaces a jump to a return, an end or another jump by that instruction, adding the
/// statements both count, where a --max-steps or --timeout stop still falls at the statement
/// it fell at before: a jump that counts no statements of its own (steps <= 0) stops only in
/// its target, whose source position the new instruction takes (a return's errors name the
/// return); a jump to an end or a jump that counts none stops only in the jump, and keeps its
/// own.
void Compiler::threadJumps() {
  for (size_t pc = 0; pc < p_.code.size(); ++pc) {
    Instr& in = p_.code[pc];
    for (int hops = 0; hops < 8 && in.op == Op::Jump && in.a < p_.code.size(); ++hops) {
      const Instr& to = p_.code[in.a];
      if ((to.op != Op::Jump && to.op != Op::Return && to.op != Op::End) || &to == &in) break;
      bool stopsInTarget = in.steps <= 0;
      bool stopsInJump = to.op != Op::Return && to.steps == 0;
      int steps = in.steps + to.steps;
      if ((!stopsInTarget && !stopsInJump) || steps < INT16_MIN || steps > INT16_MAX) break;
      if (!stopsInJump) p_.locs[pc] = p_.locs[in.a];
      in.op = to.op;
      in.flags = to.flags;
      in.a = to.a;
      in.b = to.b;
      in.c = to.c;
      in.steps = static_cast<int16_t>(steps);
    }
  }
}

}  // namespace rb::compiler
