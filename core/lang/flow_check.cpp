#include "lang/flow_check.h"

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <string>
#include <unordered_map>
#include <vector>

#include "lang/builtins.h"

namespace rb {

namespace {

/// What an event is. An event is one 32-bit word: its kind in the low 5 bits, a payload above.
/// The payloads of block events (which event pairs with which) are filled in by finish().
enum class Ev : uint8_t {
  Write,       ///< a variable assigned (payload: its number)
  Call,        ///< a sub called (payload: its span, or kNone)
  Gosub,       ///< payload: the jump (Impl::jumps)
  Goto,        ///< payload: the jump
  Label,       ///< payload: the label's number
  SubBegin,    ///< payload: the sub's span
  SubEnd,      ///< payload: the sub's span
  Robot,       ///< needs a placed robot (payload: Impl::robotUses, or kNone in a sub)
  Locate,      ///< places the robot
  If,          ///< an if's test, after its condition (payload: its next branch)
  ElseIf,      ///< falling into it from the branch before goes to the endif (payload: the endif)
  ElseIfTest,  ///< after the elseif's condition (payload: its next branch)
  Else,        ///< falling into it goes to the endif (payload: the endif)
  EndIf,
  While,       ///< the loop's head, before its condition (payload: the wend)
  WhileTest,   ///< after the condition (payload: the wend)
  Wend,        ///< payload: the while
  Repeat,      ///< payload: the until
  Until,       ///< before until's condition (payload: the until's test)
  UntilTest,   ///< after the condition (payload: the repeat)
  For,         ///< after its start, limit and step (payload: the next)
  Next,        ///< payload: the for
  Break,       ///< payload: the loop's head
  Continue,    ///< payload: the loop's head
  Return,
  End,
};

constexpr uint32_t kKindBits = 5;
constexpr uint32_t kNone = (1u << (32 - kKindBits)) - 1;  ///< the largest payload: "none"

uint32_t event(Ev kind, uint32_t payload) { return static_cast<uint32_t>(kind) | (payload << kKindBits); }
Ev kindOf(uint32_t e) { return static_cast<Ev>(e & ((1u << kKindBits) - 1)); }
uint32_t payloadOf(uint32_t e) { return e >> kKindBits; }

/// What running a sub, or the code from a label on, may do (Summary::flags).
enum : uint8_t {
  kEnds = 1,     ///< `end`
  kJumps = 2,    ///< a goto: it may leave for anywhere
  kPlaces = 4,   ///< rLocate
  kMoves = 8,    ///< a robot statement
  kUnknown = 16, ///< more than the checks follow
};

/// A sub's body or the code a gosub runs, with what it may call.
struct Summary {
  bool done = false;
  uint8_t flags = 0;
  std::vector<uint32_t> writes;   ///< variables assigned, sorted (a sub's: only global ones)
  std::vector<uint32_t> localWrites;  ///< a sub's own variables it assigns, sorted
  std::vector<uint32_t> callees;  ///< nodes: a sub's span, or the number of subs + a label
};

/// The pieces one after another (GCC 12 warns falsely, -Wrestrict, about some chains of
/// `"text" + string`).
std::string join(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (std::string_view p : parts) s.append(p);
  return s;
}

/// "'a'", "'a' or 'b'", "'a', 'b' or 'c'".
std::string nameList(const std::vector<std::string_view>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i) out += i + 1 == names.size() ? " or " : ", ";
    out.append(join({"'", names[i], "'"}));
  }
  return out;
}

}  // namespace

struct FlowChecks::Impl {
  Impl(const LoadedProgram& p, bool real) : program(p), builtins(p.builtins), realRobot(real) {
    // Room for a typical program's events at once: memory not written to is never touched.
    ev.reserve(2 * p.stmtCount() + 16);
    robotUses.reserve(p.stmtCount() / 2 + 16);
    uint32_t span = 0;
    for (const Declaration& d : p.declarations) {
      if (d.kind != ast::StmtKind::Sub) continue;
      if (!d.broken) subByName.try_emplace(d.name, span);
      subDecls.push_back(&d);
      ++span;
    }
  }

  const LoadedProgram& program;
  const BuiltinTable& builtins;
  bool realRobot;

  // ---- gathered statement by statement
  std::vector<uint32_t> ev;
  bool overflow = false;  ///< a number too large for a payload: no flow warnings
  bool commPort = false;  ///< the program may drive a real robot
  uint32_t sub = kNone;   ///< the sub being read (kNone: the main program)
  /// The last statement (labels aside) jumps away (end, goto, return, break, continue): the
  /// next one is reached only by a jump. Of the sub being read, and of the main program.
  bool afterJump = false, mainAfterJump = false;
  uint32_t lastLabel = kNone, mainLastLabel = kNone;  ///< the statement before, if it is a label
  std::vector<uint8_t> globalVar;  ///< by variable number
  std::vector<std::string_view> varNames;  ///< by variable number (a global's without its '_')
  std::unordered_map<std::string_view, uint32_t> subByName;
  std::vector<const Declaration*> subDecls;  ///< by span
  struct Label {
    std::string_view name;
    SourceLoc loc;
    uint32_t pos = kNone;    ///< its event
    uint32_t scope = kNone;  ///< the sub it is in (kNone: the main program)
    uint32_t start = kNone;  ///< where the code a jump to it runs begins (the outermost loop around it)
    bool used = false;
    bool fallenInto = true;  ///< the statement before it may go on to it
    /// Else, the label right before it, if any: when that one is reached, so is this one.
    uint32_t after = kNone;
  };
  std::unordered_map<std::string_view, uint32_t> labelByName;
  std::vector<Label> labels;
  struct Jump {
    uint32_t label;
    uint32_t scope;  ///< the sub it is in (kNone: the main program)
    SourceLoc loc;
    bool gosub;
  };
  std::vector<Jump> jumps;
  std::vector<SourceLoc> robotUses;  ///< robot statements of the main program
  /// A loop condition made of variables, constants and pure functions.
  struct Cond {
    std::vector<uint32_t> vars;
    std::vector<std::string_view> names;
    SourceLoc loc;  ///< the first variable
  };
  /// A while or repeat loop being read, and its condition if the loop check can follow it.
  struct Loop {
    uint32_t head;
    bool followed = false;
    Cond cond;
  };
  std::vector<Loop> loops;
  Cond scratch;  ///< a condition being read
  /// By variable: its last write (event + 1); the last break, goto, return or end (+ 1). A loop
  /// none of whose condition's variables is written after its head, and that nothing leaves,
  /// is a candidate.
  std::vector<uint32_t> lastWrite;
  uint32_t lastExit = 0;
  /// A loop whose condition no statement inside changes and that no statement inside leaves:
  /// it never ends unless what it calls changes the condition.
  struct Candidate {
    uint32_t head, closer;
    uint32_t scope;  ///< the sub the loop is in (kNone: the main program)
    Cond cond;
  };
  std::vector<Candidate> candidates;

  // ---- found by finish()
  size_t n = 0;
  bool broken = false;      ///< the blocks did not pair: no flow warnings
  bool unclosedIf = false;  ///< an if without endif: the robot check does not follow the flow
  std::vector<uint32_t> subEnd;  ///< by span: its SubEnd event
  std::vector<bool> subCalled;
  std::vector<Summary> subSums, labelSums;
  std::vector<uint32_t> callSites;  ///< Call and Gosub events, in order
  size_t work = 0, budget = 0;  ///< events and nodes walked for summaries, and the most allowed
  std::vector<uint32_t> stamp;  ///< by node: the walk that last saw it
  uint32_t stampNow = 0;
  static constexpr uint8_t kNotKnown = 2;
  std::vector<uint8_t> placing;  ///< by node: mayPlace(), or kNotKnown

  uint32_t checked(size_t v) {
    if (v >= kNone) {
      overflow = true;
      return 0;
    }
    return static_cast<uint32_t>(v);
  }
  uint32_t push(Ev kind, uint32_t payload = 0) {
    uint32_t at = checked(ev.size());
    ev.push_back(event(kind, payload));
    return at;
  }
  uint32_t subNumber(std::string_view name) const {
    auto it = subByName.find(name);
    return it == subByName.end() ? kNone : it->second;
  }
  uint32_t labelNumber(std::string_view name) {
    auto [it, fresh] = labelByName.try_emplace(name, static_cast<uint32_t>(labels.size()));
    if (fresh) {
      labels.emplace_back();
      labels.back().name = name;
    }
    return checked(it->second);
  }
  uint32_t labelNode(uint32_t label) const { return static_cast<uint32_t>(subDecls.size()) + label; }

  // ---- reading statements

  void statement(const ast::Stmt& s, const Resolve& resolve) {
    events(s, resolve);
    using K = ast::StmtKind;
    if (s.kind != K::Label) {  // a label is the last label (events())
      afterJump = s.kind == K::End || s.kind == K::Goto || s.kind == K::Return || s.kind == K::Break ||
                  s.kind == K::Continue;
      lastLabel = kNone;
    }
  }

  void events(const ast::Stmt& s, const Resolve& resolve) {
    using K = ast::StmtKind;
    switch (s.kind) {
      case K::If:
        expr(s.value);
        push(Ev::If);
        break;
      case K::IfLine:
        expr(s.value);
        push(Ev::If);
        if (!s.body.empty()) events(*s.body[0], resolve);
        if (s.body.size() > 1) {
          push(Ev::Else);
          events(*s.body[1], resolve);
        }
        push(Ev::EndIf);
        break;
      case K::ElseIf:
        push(Ev::ElseIf);
        expr(s.value);
        push(Ev::ElseIfTest);
        break;
      case K::Else: push(Ev::Else); break;
      case K::EndIf: push(Ev::EndIf); break;
      case K::For:
        for (const ast::Expr* e : s.exprs) expr(e);
        push(Ev::For);
        break;
      case K::Next: push(Ev::Next); break;
      case K::While:
        beginLoop(push(Ev::While));
        condition(s.value, resolve);
        expr(s.value);
        push(Ev::WhileTest);
        break;
      case K::Wend: endLoop(push(Ev::Wend)); break;
      case K::Repeat: beginLoop(push(Ev::Repeat)); break;
      case K::Until:
        push(Ev::Until);
        condition(s.value, resolve);
        expr(s.value);
        endLoop(push(Ev::UntilTest));
        break;
      case K::Break: exit(Ev::Break); break;
      case K::Continue: push(Ev::Continue); break;
      case K::Goto:
      case K::Gosub: {
        uint32_t label = labelNumber(s.name);
        jumps.push_back(Jump{label, sub, s.nameLoc.valid() ? s.nameLoc : s.loc, s.kind == K::Gosub});
        uint32_t jump = checked(jumps.size() - 1);
        if (s.kind == K::Gosub) push(Ev::Gosub, jump);
        else exit(Ev::Goto, jump);
        break;
      }
      case K::Return:
        expr(s.value);
        exit(Ev::Return);
        break;
      case K::End: exit(Ev::End); break;
      case K::Label: {
        uint32_t label = labelNumber(s.name);
        Label& l = labels[label];
        if (l.pos == kNone) {
          l.pos = checked(ev.size());
          l.scope = sub;
          l.loc = s.nameLoc.valid() ? s.nameLoc : s.loc;
          l.fallenInto = !afterJump;
          if (afterJump) l.after = lastLabel;
        }
        push(Ev::Label, label);
        lastLabel = label;
        break;
      }
      case K::Call:
        for (const ast::Expr* e : s.exprs) expr(e);
        push(Ev::Call, subNumber(s.name));
        break;
      case K::Command:
        for (const ast::Expr* e : s.exprs) expr(e);
        if (const Builtin* b = builtins.find(s.name, BuiltinKind::Command)) builtin(*b, s.loc);
        break;
      case K::Sub:
      case K::EndSub:
      case K::Include: break;
      default:  // assignment, print, input, dim, data
        expr(s.target);
        expr(s.value);
        for (const ast::Expr* e : s.exprs) expr(e);
        break;
    }
  }

  /// Calls in an expression, innermost first: subs, and the robot's built-ins.
  void expr(const ast::Expr* e) {
    if (!e) return;
    for (const ast::Expr* a : e->args) expr(a);
    if (e->kind != ast::ExprKind::Call) return;
    if (const Builtin* b = builtins.find(e->text, BuiltinKind::Function)) builtin(*b, e->loc);
    else push(Ev::Call, subNumber(e->text));
  }

  void builtin(const Builtin& b, SourceLoc loc) {
    if (b.traits & trait::kNeedsRobot) {
      if (sub == kNone) {
        push(Ev::Robot, checked(robotUses.size()));
        robotUses.push_back(loc);
      } else {
        push(Ev::Robot, kNone);
      }
    }
    if (b.traits & trait::kPlacesRobot) push(Ev::Locate);
    if (b.traits & trait::kRealRobot) commPort = true;
  }

  /// An event that may leave a loop.
  void exit(Ev kind, uint32_t payload = 0) { lastExit = push(kind, payload) + 1; }

  /// Notes the condition of the loop being read, if the loop check can follow it: variables,
  /// constants and pure functions, with at least one variable (a constant condition is written
  /// on purpose).
  void condition(const ast::Expr* e, const Resolve& resolve) {
    scratch.vars.clear();
    scratch.names.clear();
    scratch.loc = SourceLoc{};
    if (loops.empty() || !conditionNames(e, scratch, resolve) || scratch.vars.empty()) return;
    loops.back().followed = true;
    loops.back().cond = scratch;
  }

  void beginLoop(uint32_t head) {
    loops.emplace_back();
    loops.back().head = head;
  }

  /// The end of the innermost while or repeat loop, at event `closer`.
  void endLoop(uint32_t closer) {
    if (loops.empty()) return;  // an error, reported by the compiler
    Loop loop = std::move(loops.back());
    loops.pop_back();
    if (!loop.followed || lastExit > loop.head) return;
    for (uint32_t var : loop.cond.vars)
      if (lastWrite[var] > loop.head) return;
    candidates.push_back(Candidate{loop.head, closer, sub, std::move(loop.cond)});
  }

  bool conditionNames(const ast::Expr* e, Cond& c, const Resolve& resolve) {
    if (!e) return true;
    switch (e->kind) {
      case ast::ExprKind::Var: {
        if (builtins.findAny(e->text)) return true;  // a constant
        // An array may change element by element, through any name it is passed by.
        if (program.arrays.count(e->text) || program.arrays.count(ast::globalName(e->text))) return false;
        uint32_t var = resolve(e->text);
        if (std::find(c.vars.begin(), c.vars.end(), var) == c.vars.end()) {
          c.vars.push_back(var);
          c.names.push_back(e->text);
          if (!c.loc.valid()) c.loc = e->loc;
        }
        return true;
      }
      case ast::ExprKind::Index: return false;
      case ast::ExprKind::Call: {
        const Builtin* b = builtins.find(e->text, BuiltinKind::Function);
        if (!b || !(b->traits & trait::kPure)) return false;  // a sub, a sensor, the timer, input
        break;
      }
      default: break;
    }
    for (const ast::Expr* a : e->args)
      if (!conditionNames(a, c, resolve)) return false;
    return true;
  }

  // ---- deciding

  void setPayload(uint32_t i, uint32_t payload) { ev[i] = event(kindOf(ev[i]), payload); }

  /// Pairs the blocks, and on the way: what each sub does, which subs are called and which
  /// labels used, where the code a jump to a label runs begins, and the loops whose condition
  /// no statement inside them changes (the candidates, before what they call is known).
  void pair() {
    struct Open {
      Ev kind;
      uint32_t at;
      uint32_t test = kNone;  ///< an if's last test, a while's test, a repeat's until
      size_t pending = 0;     ///< an if's first else or elseif in `pending`
    };
    std::vector<Open> open;
    std::vector<uint32_t> pending;  // else and elseif events waiting for their endif
    uint32_t cur = kNone;
    size_t spans = subDecls.size();
    subEnd.assign(spans, kNone);
    subCalled.assign(spans, false);
    subSums.assign(spans, Summary{});
    // An if still open at a sub or at the end runs to that point (rb-unclosed-if); loops
    // cannot be open there in a program without errors.
    auto closeBlocks = [&](uint32_t at) {
      for (auto it = open.rbegin(); it != open.rend(); ++it) {
        if (it->kind != Ev::If) {
          broken = true;
          continue;
        }
        unclosedIf = true;
        if (it->test != kNone) setPayload(it->test, at);
        for (size_t k = it->pending; k < pending.size(); ++k) setPayload(pending[k], at);
        pending.resize(it->pending);
      }
      open.clear();
    };
    auto top = [&](Ev kind) -> Open* {
      if (open.empty() || open.back().kind != kind) {
        broken = true;
        return nullptr;
      }
      return &open.back();
    };
    for (uint32_t i = 0; i < n && !broken; ++i) {
      Ev k = kindOf(ev[i]);
      uint32_t p = payloadOf(ev[i]);
      Summary* own = cur != kNone ? &subSums[cur] : nullptr;
      switch (k) {
        case Ev::SubBegin:
          closeBlocks(i);
          cur = p;
          break;
        case Ev::SubEnd:
          closeBlocks(i);
          subEnd[p] = i;
          cur = kNone;
          break;
        case Ev::Write:
          if (own) (globalVar[p] ? own->writes : own->localWrites).push_back(p);
          break;
        case Ev::Call:
          callSites.push_back(i);
          if (p == kNone) {
            if (own) own->flags |= kUnknown;
          } else {
            if (p != cur) subCalled[p] = true;
            if (own) own->callees.push_back(p);
          }
          break;
        case Ev::Gosub:
        case Ev::Goto: {
          uint32_t label = jumps[p].label;
          labels[label].used = true;
          if (k == Ev::Gosub) callSites.push_back(i);
          if (own) {
            own->callees.push_back(labelNode(label));
            if (k == Ev::Goto) own->flags |= kJumps;
            if (foreign(label, cur)) own->flags |= kUnknown;
          }
          break;
        }
        case Ev::Label: {
          Label& l = labels[p];
          if (l.pos != i) break;
          l.start = i;
          for (const Open& o : open) {
            if (o.kind != Ev::If) {
              l.start = o.at;
              break;
            }
          }
          break;
        }
        case Ev::Robot:
          if (own) own->flags |= kMoves;
          break;
        case Ev::Locate:
          if (own) own->flags |= kPlaces;
          break;
        case Ev::End:
          if (own) own->flags |= kEnds;
          break;
        case Ev::Return: break;
        case Ev::Break:
        case Ev::Continue: {
          auto isLoop = [](const Open& o) { return o.kind != Ev::If; };
          auto loop = std::find_if(open.rbegin(), open.rend(), isLoop);
          if (loop == open.rend()) {
            broken = true;
            break;
          }
          setPayload(i, loop->at);
          break;
        }
        case Ev::If: open.push_back(Open{Ev::If, i, i, pending.size()}); break;
        case Ev::ElseIf:
        case Ev::Else:
          if (Open* o = top(Ev::If)) {
            if (o->test != kNone) setPayload(o->test, i);
            o->test = kNone;
            pending.push_back(i);
          }
          break;
        case Ev::ElseIfTest:
          if (Open* o = top(Ev::If)) o->test = i;
          break;
        case Ev::EndIf:
          if (Open* o = top(Ev::If)) {
            if (o->test != kNone) setPayload(o->test, i);
            for (size_t j = o->pending; j < pending.size(); ++j) setPayload(pending[j], i);
            pending.resize(o->pending);
            open.pop_back();
          }
          break;
        case Ev::While: open.push_back(Open{Ev::While, i}); break;
        case Ev::WhileTest:
          if (Open* o = top(Ev::While)) o->test = i;
          break;
        case Ev::Wend:
          if (Open* o = top(Ev::While)) {
            setPayload(o->at, i);
            if (o->test != kNone) setPayload(o->test, i);
            setPayload(i, o->at);
            open.pop_back();
          }
          break;
        case Ev::Repeat: open.push_back(Open{Ev::Repeat, i}); break;
        case Ev::Until:
          if (Open* o = top(Ev::Repeat)) {
            o->test = i;
            setPayload(o->at, i);
          }
          break;
        case Ev::UntilTest:
          if (Open* o = top(Ev::Repeat)) {
            if (o->test == kNone) {
              broken = true;
              break;
            }
            setPayload(o->test, i);
            setPayload(i, o->at);
            open.pop_back();
          }
          break;
        case Ev::For: open.push_back(Open{Ev::For, i}); break;
        case Ev::Next:
          if (Open* o = top(Ev::For)) {
            setPayload(o->at, i);
            setPayload(i, o->at);
            open.pop_back();
          }
          break;
      }
    }
    closeBlocks(static_cast<uint32_t>(n));
    for (Summary& s : subSums) {
      for (std::vector<uint32_t>* v : {&s.writes, &s.localWrites}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
      }
      s.done = true;
    }
    labelSums.assign(labels.size(), Summary{});
  }

  /// A jump from code of `scope` into another sub's body: its code runs on a frame not its own,
  /// where the checks cannot tell which variable is which.
  bool foreign(uint32_t label, uint32_t scope) const {
    uint32_t into = labels[label].scope;
    return into != kNone && into != scope;
  }

  /// What the code from a label on may do: from the label (or the outermost loop around it,
  /// which comes back to code before the label) to the first `return` that every path from
  /// there reaches, or to the end of its sub or of the program, jumping over subs.
  Summary& labelSummary(uint32_t label) {
    Summary& s = labelSums[label];
    if (s.done) return s;
    s.done = true;
    const Label& l = labels[label];
    if (l.start == kNone) {
      s.flags = kUnknown;
      return s;
    }
    int depth = 0, low = 0;  // blocks open, and the fewest since the start
    bool stop = false;
    for (uint32_t i = l.start; i < n && !stop; ++i) {
      if (++work > budget) {
        s.flags |= kUnknown;
        break;
      }
      uint32_t p = payloadOf(ev[i]);
      switch (kindOf(ev[i])) {
        case Ev::SubBegin:
          if (l.scope == kNone && subEnd[p] != kNone) i = subEnd[p];  // falling into a sub skips it
          else stop = true;
          break;
        case Ev::SubEnd: stop = true; break;  // the end of the label's sub: it returns
        case Ev::Write: s.writes.push_back(p); break;
        case Ev::Call:
          if (p == kNone) s.flags |= kUnknown;
          else s.callees.push_back(p);
          break;
        case Ev::Gosub:
        case Ev::Goto:
          s.callees.push_back(labelNode(jumps[p].label));
          if (kindOf(ev[i]) == Ev::Goto) s.flags |= kJumps;
          if (foreign(jumps[p].label, l.scope)) s.flags |= kUnknown;
          break;
        case Ev::End: s.flags |= kEnds; break;
        case Ev::Robot: s.flags |= kMoves; break;
        case Ev::Locate: s.flags |= kPlaces; break;
        case Ev::If:
        case Ev::While:
        case Ev::Repeat:
        case Ev::For: ++depth; break;
        case Ev::ElseIf:
        case Ev::Else: low = std::min(low, depth - 1); break;
        case Ev::EndIf:
        case Ev::Wend:
        case Ev::Until:
        case Ev::Next:
          --depth;
          low = std::min(low, depth);
          break;
        case Ev::Return: stop = depth == low; break;
        default: break;
      }
    }
    std::sort(s.writes.begin(), s.writes.end());
    s.writes.erase(std::unique(s.writes.begin(), s.writes.end()), s.writes.end());
    return s;
  }

  Summary& summary(uint32_t node) {
    return node < subSums.size() ? subSums[node] : labelSummary(node - static_cast<uint32_t>(subSums.size()));
  }

  /// Walks everything `roots` may run, sub by sub and label by label; `visit` returns false to
  /// stop (then so does walk(), with false, as it does past the budget).
  template <typename Visit>
  bool walk(std::vector<uint32_t> todo, Visit visit) {
    if (stamp.empty()) stamp.assign(subSums.size() + labels.size(), 0);
    ++stampNow;
    while (!todo.empty()) {
      uint32_t node = todo.back();
      todo.pop_back();
      if (stamp[node] == stampNow) continue;
      stamp[node] = stampNow;
      if (++work > budget) return false;
      const Summary& s = summary(node);
      if (!visit(node, s)) return false;
      for (uint32_t c : s.callees) todo.push_back(c);
    }
    return true;
  }

  /// Whether what `node` runs (with what that calls) may place the robot, or use it, which stops
  /// the program when it is not placed: after it, the robot may be placed. Asked only where the
  /// robot is not placed yet, which in most programs is nowhere past their first lines.
  bool mayPlace(uint32_t node) {
    if (node == kNone) return true;
    if (placing.empty()) placing.assign(subSums.size() + labels.size(), kNotKnown);
    if (placing[node] == kNotKnown)
      placing[node] = !walk({node}, [](uint32_t, const Summary& s) { return !(s.flags & (kPlaces | kMoves | kUnknown)); });
    return placing[node];
  }

  /// The node a call or gosub event runs (kNone: a sub the checks do not know).
  uint32_t callee(uint32_t i) const {
    uint32_t p = payloadOf(ev[i]);
    if (kindOf(ev[i]) == Ev::Gosub) return labelNode(jumps[p].label);
    return p;
  }

  // ---- the checks

  void endlessLoops(DiagnosticList& diags) {
    for (const Candidate& c : candidates) {
      const Cond& cond = c.cond;
      std::vector<uint32_t> roots;
      bool unknown = false;
      auto from = std::upper_bound(callSites.begin(), callSites.end(), c.head);
      for (auto it = from; it != callSites.end() && *it < c.closer; ++it) {
        uint32_t node = callee(*it);
        bool intoSub = kindOf(ev[*it]) == Ev::Gosub && foreign(jumps[payloadOf(ev[*it])].label, c.scope);
        if (node == kNone || intoSub) unknown = true;
        else roots.push_back(node);
      }
      if (unknown) continue;
      std::vector<std::pair<uint32_t, uint32_t>> shadows;  // a sub, and a global it has a local of
      bool stays = walk(roots, [&](uint32_t node, const Summary& s) {
        if (s.flags & (kEnds | kJumps | kUnknown)) return false;
        for (uint32_t var : cond.vars) {
          if (std::binary_search(s.writes.begin(), s.writes.end(), var)) return false;
          if (!globalVar[var]) continue;
          for (uint32_t local : s.localWrites)
            if (varNames[local] == varNames[var]) shadows.emplace_back(node, var);
        }
        return true;
      });
      if (!stays) continue;
      std::string names = nameList(cond.names);
      diags.warning(cond.loc, join({"this loop never ends once it repeats: nothing in it changes ", names}),
                    "rb-endless-loop");
      // A sub that sets a variable of that name sets its own: the mistake is likely there.
      for (const auto& [node, var] : shadows) {
        const Declaration& d = *subDecls[node];
        std::string_view name = varNames[var];
        diags.note(d.nameLoc.valid() ? d.nameLoc : d.loc,
                   join({"sub '", d.name, "' changes its own '", name, "', not the main program's (that is '_",
                         name, "' in the sub)"}));
      }
    }
  }

  /// Robot statements of the main program that every way to them reaches without rLocate: a
  /// forward walk of the main program (subs are skipped, calls and gosubs summarized) with, for
  /// each event, whether it is reached at all and whether some way to it may have placed the
  /// robot.
  void unplacedRobot(DiagnosticList& diags) {
    if (realRobot || commPort || unclosedIf || robotUses.empty() || n == 0) return;
    constexpr uint8_t kUnreached = 0, kUnplaced = 1, kMaybePlaced = 2;
    std::vector<uint8_t> state(n, kUnreached);
    std::vector<uint32_t> todo;
    auto reach = [&](uint32_t to, uint8_t s) {
      if (s == kUnreached || to >= n || state[to] >= s) return;
      state[to] = s;
      todo.push_back(to);
    };
    // Labels of the main program that code in a sub jumps to: anything may have happened.
    for (const Jump& j : jumps) {
      const Label& l = labels[j.label];
      if (j.scope != kNone && l.scope == kNone && l.pos != kNone) reach(l.pos, kMaybePlaced);
    }
    reach(0, kUnplaced);
    // Where an if's test goes when it fails: into the next branch, or to the endif.
    auto branch = [&](uint32_t next) {
      Ev k = next < n ? kindOf(ev[next]) : Ev::EndIf;
      return k == Ev::ElseIf || k == Ev::Else ? next + 1 : next;
    };
    auto pay = [&](uint32_t i) { return payloadOf(ev[i]); };
    while (!todo.empty()) {
      uint32_t i = todo.back();
      todo.pop_back();
      uint8_t s = state[i];
      uint32_t p = pay(i);
      switch (kindOf(ev[i])) {
        case Ev::SubBegin:
          if (subEnd[p] != kNone) reach(subEnd[p] + 1, s);
          break;
        case Ev::SubEnd: break;
        case Ev::Robot: reach(i + 1, s == kUnplaced ? kUnreached : s); break;  // unplaced: it stops
        case Ev::Locate: reach(i + 1, kMaybePlaced); break;
        case Ev::Call: reach(i + 1, mayPlace(p) ? kMaybePlaced : s); break;
        case Ev::Gosub: {
          const Label& l = labels[jumps[p].label];
          if (l.scope == kNone && l.pos != kNone) reach(l.pos, s);
          reach(i + 1, mayPlace(labelNode(jumps[p].label)) ? kMaybePlaced : s);
          break;
        }
        case Ev::Goto: {
          const Label& l = labels[jumps[p].label];
          if (l.scope == kNone && l.pos != kNone) reach(l.pos, s);
          break;
        }
        case Ev::Return:
        case Ev::End: break;
        case Ev::If:
        case Ev::ElseIfTest:
          reach(i + 1, s);
          reach(branch(p), s);
          break;
        case Ev::ElseIf:
        case Ev::Else: reach(p, s); break;
        case Ev::WhileTest:
          reach(i + 1, s);
          reach(p + 1, s);
          break;
        case Ev::Wend: reach(p, s); break;
        case Ev::UntilTest:
          reach(p + 1, s);
          reach(i + 1, s);
          break;
        case Ev::For:
          reach(i + 1, s);
          reach(p + 1, s);
          break;
        case Ev::Next:
          reach(p + 1, s);
          reach(i + 1, s);
          break;
        case Ev::Break: {
          uint32_t head = p;
          uint32_t closer = pay(head);  // wend, until or next
          if (kindOf(ev[head]) == Ev::Repeat) closer = pay(closer);  // the until's test
          reach(closer + 1, s);
          break;
        }
        case Ev::Continue: {
          uint32_t head = p;
          Ev k = kindOf(ev[head]);
          reach(k == Ev::While ? head : pay(head), s);  // the while's test, the until, the next
          break;
        }
        default: reach(i + 1, s); break;
      }
    }
    for (uint32_t i = 0; i < n; ++i) {
      if (kindOf(ev[i]) != Ev::Robot || state[i] != kUnplaced || pay(i) == kNone) continue;
      SourceLoc loc = robotUses[pay(i)];
      std::string name = wordAt(loc);
      diags.warning(loc, join({"the robot is not placed yet when '", name, "' runs: rLocate x, y places it"}),
                    "rb-robot-not-placed");
    }
  }

  /// The name written at `loc`.
  std::string wordAt(SourceLoc loc) const {
    std::string_view line = program.sources.file(loc.file).lineText(loc.line);
    size_t from = loc.col - 1, to = from;
    while (to < line.size() && (std::isalnum(static_cast<unsigned char>(line[to])) || line[to] == '_')) ++to;
    return std::string(line.substr(from, to - from));
  }

  void jumpsIntoSubs(DiagnosticList& diags) {
    for (const Jump& j : jumps) {
      const Label& l = labels[j.label];
      if (l.pos == kNone || l.scope == kNone || l.scope == j.scope) continue;
      std::string label(l.name);
      std::string msg = "label '";
      msg.append(label).append("' is inside sub '").append(subDecls[l.scope]->name);
      msg.append("': a ").append(j.gosub ? "gosub" : "goto");
      msg.append(" from outside the sub runs its code without the sub's variables; call the sub, or "
                 "move the label out of it");
      diags.warning(j.loc, std::move(msg), "rb-jump-into-sub");
      diags.note(l.loc, join({"'", label, "' is defined here"}));
    }
  }

  /// Subs and labels of the main file (not of included libraries) that nothing uses.
  void unused(DiagnosticList& diags) {
    // A library's idiom (lib/RB-9.bas): its first jump is a goto over its own routines, which
    // the programs that include it call. What lies between that goto and its label is used
    // from outside the file, so it is not reported.
    uint32_t skipFrom = 0, skipTo = 0;
    for (const Jump& j : jumps) {
      if (j.loc.file != 0) continue;
      const Label& target = labels[j.label];
      if (!j.gosub && j.scope == kNone && target.loc.file == 0 && target.loc.line > j.loc.line) {
        skipFrom = j.loc.line;
        skipTo = target.loc.line;
      }
      break;
    }
    auto jumpedOver = [&](SourceLoc loc) { return loc.line > skipFrom && loc.line < skipTo; };
    for (size_t k = 0; k < subDecls.size(); ++k) {
      const Declaration& d = *subDecls[k];
      if (d.broken || d.loc.file != 0 || subCalled[k] || jumpedOver(d.loc)) continue;
      diags.warning(d.nameLoc.valid() ? d.nameLoc : d.loc, join({"sub '", d.name, "' is never called"}),
                    "rb-unused-sub");
    }
    // A label the code before it falls into is a marker (`Main:`); one it does not is the start
    // of code that only a jump could run.
    for (const Label& l : labels) {
      if (l.pos == kNone || l.loc.file != 0 || l.used || reached(l) || jumpedOver(l.loc)) continue;
      std::string_view why = "' is never used: no goto or gosub jumps to it, so the code after it never runs";
      diags.warning(l.loc, join({"label '", l.name, why}), "rb-unused-label");
    }
  }

  /// Whether the code before a label may go on to it: directly, or through the labels right
  /// before it (`A:` `B:` after an `end`: B is reached when A is used).
  bool reached(const Label& label) const {
    const Label* l = &label;
    for (size_t steps = 0; steps <= labels.size(); ++steps) {
      if (l->fallenInto) return true;
      if (l->after == kNone) return false;
      l = &labels[l->after];
      if (l->used) return true;
    }
    return true;
  }

  void finish(DiagnosticList& diags) {
    if (diags.hasErrors() || overflow) return;
    n = ev.size();
    budget = 8 * n + 1'000'000;
    pair();
    if (broken) return;
    endlessLoops(diags);
    unplacedRobot(diags);
    jumpsIntoSubs(diags);
    unused(diags);
  }
};

FlowChecks::FlowChecks(const LoadedProgram& program, bool realRobot)
    : impl_(std::make_unique<Impl>(program, realRobot)) {}
FlowChecks::~FlowChecks() = default;

void FlowChecks::declareVariable(uint32_t var, bool global, std::string_view name) {
  if (var >= impl_->globalVar.size()) {
    impl_->globalVar.resize(var + 1, 0);
    impl_->lastWrite.resize(var + 1, 0);
    impl_->varNames.resize(var + 1);
  }
  impl_->globalVar[var] = global;
  impl_->varNames[var] = name;
}
void FlowChecks::enterSub(size_t span) {
  if (impl_->sub == kNone) {
    impl_->mainAfterJump = impl_->afterJump;
    impl_->mainLastLabel = impl_->lastLabel;
  }
  impl_->afterJump = false;  // a call runs the sub's first statement
  impl_->lastLabel = kNone;
  impl_->sub = impl_->checked(span);
  impl_->loops.clear();  // a loop left open is an error
  impl_->push(Ev::SubBegin, impl_->sub);
}
void FlowChecks::leaveSub() {
  if (impl_->sub == kNone) return;
  impl_->push(Ev::SubEnd, impl_->sub);
  impl_->sub = kNone;
  impl_->afterJump = impl_->mainAfterJump;  // falling into a sub goes past it
  impl_->lastLabel = impl_->mainLastLabel;
}
void FlowChecks::statement(const ast::Stmt& s, const Resolve& resolve) { impl_->statement(s, resolve); }
void FlowChecks::write(uint32_t var) {
  uint32_t at = impl_->push(Ev::Write, impl_->checked(var));
  if (var < impl_->lastWrite.size()) impl_->lastWrite[var] = at + 1;
}
void FlowChecks::finish(DiagnosticList& diags) { impl_->finish(diags); }

}  // namespace rb
