// Arrays as a whole (MaxDim, mFromString), the clipboard, files and other programs. Files and
// processes go through the host's SystemAccess, which decides what a program may reach.
#include "base/runtime_error.h"
#include "machine/builtins_impl.h"

namespace rb::builtins {

namespace {

const ArrObj& arrayArg(Args& a, int i) {
  if (!a[i].isArr()) throw RuntimeError(a.describe(i) + " must be an array");
  return a[i].arr();
}

SystemAccess& system(Machine& m, std::string_view who) {
  SystemAccess* s = m.host().system();
  if (!s) throw RuntimeError(std::string(who) + ": this run has no access to files or programs");
  return *s;
}

}  // namespace

Value arrMaxDim(Machine&, Args& a) {
  const ArrObj& arr = arrayArg(a, 0);
  int64_t d = a.has(1) ? a.integer(1) : 1;
  if (d < 1 || d > static_cast<int64_t>(arr.dims.size()))
    throw RuntimeError(a.describe(1) + " must be a dimension of the array: 1.." +
                       std::to_string(arr.dims.size()) + ", got " + std::to_string(d));
  return Value::integer(arr.dims[static_cast<size_t>(d - 1)]);
}

namespace {

/// What the allocator takes for a block of n bytes (glibc's malloc: n and 8 bytes, in 16s).
constexpr uint64_t allocated(uint64_t n) { return (n + 8 + 15) / 16 * 16; }

/// The memory a string value of `length` characters takes beyond its array element: its StrObj
/// and, past the few characters std::string keeps inside itself, its text.
uint64_t stringBytes(size_t length) {
  static const size_t inPlace = std::string().capacity();
  return allocated(sizeof(StrObj)) + (length > inPlace ? allocated(length + 1) : 0);
}

}  // namespace

Value arrFromString(Machine& m, Args& a) {
  const std::string& s = a.str(1);
  const std::string& delim = a.has(2) ? a.str(2) : std::string(",");
  if (delim.empty()) throw RuntimeError(a.describe(2) + " must not be empty");
  // The fields are counted first, and what they will take measured, without making anything:
  // the array and its strings must fit in --max-memory before any of them is made. Taking every
  // field for a string bounds what they take; only when that bound does not fit are the fields
  // that spell numbers (they take no string) told apart, which reads the fields once more.
  uint64_t fields = 0, bound = 0;
  forEachField(m, s, delim, [&](std::string_view field) {
    ++fields;
    bound += sizeof(Value) + stringBytes(field.size());
    return true;
  });
  if (fields > kMaxArrayElements)
    throw RuntimeError("mFromString: " + std::to_string(fields) + " fields are too many for one array (at most " +
                       std::to_string(kMaxArrayElements) + ")");
  if (!m.memoryFits(bound)) {
    uint64_t need = 0;
    forEachField(m, s, delim, [&](std::string_view field) {
      Value number;
      need += sizeof(Value) + (parseNumber(field, number) ? 0 : stringBytes(field.size()));
      return true;
    });
    m.reserveMemory(need, "mFromString's " + std::to_string(fields) + " fields");
  }
  Value arr = Value::array({static_cast<int64_t>(fields)});
  auto& items = arr.arr().items;
  size_t i = 0;
  forEachField(m, s, delim, [&](std::string_view field) {
    // A field that spells a number is a number (so that `round(a[3])` works), else a string.
    Value& v = items[i++];
    if (!parseNumber(field, v)) v = Value::string(std::string(field));
    return true;
  });
  a[0] = std::move(arr);
  return {};
}

Value sysGetClipboard(Machine& m, Args&) { return Value::string(m.clipboard); }

Value sysSetClipboard(Machine& m, Args& a) {
  m.clipboard = formatValue(a[0]);
  m.host().clipboardChanged(m.clipboard);
  return {};
}

Value sysFileExists(Machine& m, Args& a) {
  return Value::boolean(system(m, "FileExists").fileExists("FileExists", a.str(0)));
}

Value sysFileRename(Machine& m, Args& a) {
  system(m, "FileRename").renameFile("FileRename", a.str(0), a.str(1));
  return {};
}

Value sysDirSet(Machine& m, Args& a) {
  system(m, "DirSet").setDirectory("DirSet", a.str(0));
  return {};
}

Value sysSpawn(Machine& m, Args& a) {
  bool wait = a.has(1) && a.integer(1) != kSpawnNoWait;
  return Value::integer(system(m, "Spawn").spawn("Spawn", a.str(0), wait, [&m] { m.checkAlarms(); }));
}

void appendSystemBuiltins(std::vector<Builtin>& t) {
  using K = BuiltinKind;
  std::vector<Builtin> rows = {
      {"MaxDim", K::Function, "array", "array [, dimension]", arrMaxDim, 0,
       "the size of a dimension of the array (1 = the first, the default)"},
      {"mFromString", K::Command, "array", "&array, s [, delimiter]", arrFromString, 0,
       "makes the array the fields of s split at delimiter (default \",\"); fields that are "
       "numbers become numbers"},
      {"GetCBtext", K::Function, "system", "", sysGetClipboard, 0,
       "the text on the clipboard (the run's own; \"\" at the start)"},
      {"SetCBtext", K::Command, "system", "text", sysSetClipboard, 0, "puts text on the clipboard"},
      {"FileExists", K::Function, "system", "name", sysFileExists, 0,
       "1 if the file exists (inside the folders this run may reach), else 0"},
      {"FileRename", K::Command, "system", "old, new", sysFileRename, 0, "renames a file"},
      {"DirSet", K::Command, "system", "folder", sysDirSet, 0,
       "the folder later relative file names start from"},
      {"Spawn", K::Function, "system", "command [, mode]", sysSpawn, 0,
       "runs another program (only with rb run --allow-spawn): P_NOWAIT returns 1 once it "
       "started, any other mode waits and returns its exit status"},
      {"P_NOWAIT", K::Constant, "system", "", nullptr, kSpawnNoWait, "Spawn's mode: do not wait"},
  };
  t.insert(t.end(), rows.begin(), rows.end());
}

}  // namespace rb::builtins
