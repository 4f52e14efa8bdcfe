#include "server.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>

#include "analysis.h"
#include "base/rules.h"
#include "lang/builtins.h"
#include "lang/token.h"
#include "transport.h"

namespace rb::lsp {

using json = nlohmann::json;

namespace {

// JSON-RPC and LSP error codes.
constexpr int kParseError = -32700;
constexpr int kInvalidRequest = -32600;
constexpr int kMethodNotFound = -32601;
constexpr int kInvalidParams = -32602;
constexpr int kInternalError = -32603;
constexpr int kServerNotInitialized = -32002;

// LSP enumerations used here.
constexpr int kSeverityError = 1, kSeverityWarning = 2;
constexpr int kSymbolFunction = 12, kSymbolKey = 20;
constexpr int kItemFunction = 3, kItemVariable = 6, kItemKeyword = 14, kItemConstant = 21,
              kItemReference = 18;
constexpr int kFullSync = 1;

/// The command that runs a file, offered as a code lens; the editor's extension carries it out.
constexpr const char* kRunCommand = "rb.runFile";

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// "rForward distance", "sqrt(x)", "Red": how a built-in is written.
std::string usageOf(const Builtin& b) {
  std::string usage(b.name);
  if (b.kind == BuiltinKind::Function) {
    usage += '(';
    usage += b.signature;
    usage += ')';
  } else if (b.kind == BuiltinKind::Command && !b.signature.empty()) {
    usage += ' ';
    usage += b.signature;
  }
  return usage;
}

const char* kindWord(BuiltinKind k) {
  switch (k) {
    case BuiltinKind::Command: return "command";
    case BuiltinKind::Function: return "function";
    case BuiltinKind::Constant: return "constant";
  }
  return "";
}

/// Markdown for one built-in: the usage line as code, the description, its group and kind.
std::string builtinDoc(const Builtin& b) {
  std::string s = "```robotbasic\n";
  s += usageOf(b);
  s += "\n```\n";
  s += b.help;
  if (b.kind == BuiltinKind::Constant) s += " (= " + std::to_string(b.constant) + ")";
  s += "\n\n*";
  s += b.group;
  s += ' ';
  s += kindWord(b.kind);
  s += '*';
  return s;
}

/// The keywords, as language.md describes them: how each is written and what it does.
struct KeywordHelp {
  std::string_view word;
  std::string_view usage;
  std::string_view help;
};
constexpr KeywordHelp kKeywords[] = {
    {"if", "if cond then statement [else statement]\nif cond\n  ...\n[elseif cond]\n[else]\nendif",
     "runs statements when cond is not 0; a block `if` ends at `endif` (or `end if`)"},
    {"then", "if cond then statement", "the statement a single-line `if` runs (at the end of a line: a block `if`)"},
    {"else", "if cond then s1 else s2\nelse", "what runs when the `if` condition is 0"},
    {"elseif", "elseif cond", "another condition of a block `if` (`else if` means the same)"},
    {"endif", "endif", "ends a block `if` (also `end if`)"},
    {"end", "end", "stops the program (`end if` and `end sub` close blocks)"},
    {"for", "for v = start to limit [step s]\n  ...\nnext [v]",
     "counts v from start to limit; limit and step are evaluated once"},
    {"to", "for v = start to limit", "the limit of a `for` loop"},
    {"step", "for v = start to limit step s", "what a `for` loop adds each pass (default 1; 0 is an error)"},
    {"next", "next [v]", "ends a `for` loop (naming its variable, if given)"},
    {"while", "while cond\n  ...\nwend", "repeats while cond is not 0, testing before each pass"},
    {"wend", "wend", "ends a `while` loop"},
    {"repeat", "repeat\n  ...\nuntil cond", "repeats until cond is not 0, testing after each pass"},
    {"until", "until cond", "ends a `repeat` loop"},
    {"break", "break", "leaves the innermost loop"},
    {"continue", "continue", "goes to the innermost loop's next test"},
    {"goto", "goto Label", "jumps to a label (labels are case-sensitive)"},
    {"gosub", "gosub Label", "calls the code at a label; `return` comes back"},
    {"return", "return [value]", "comes back from a `gosub` or a sub (a sub may return a value)"},
    {"sub", "sub Name(a, &b)\n  ...\nendsub",
     "a sub with local variables; `&` parameters are copied back to the caller"},
    {"endsub", "endsub", "ends a sub (also `end sub`)"},
    {"call", "call Name(args)", "calls a sub (`Name(args)` alone does too)"},
    {"dim", "dim a[n], grid[rows, cols]", "makes arrays (elements 0 to n-1, all 0); arrays are global"},
    {"data", "data name; v1, v2, ...", "appends values to the one-dimensional array name"},
    {"print", "print item, item; item", "`,` joins items, `;` puts a tab; a trailing `,` or `;` keeps the line open"},
    {"input", "input \"prompt\", var", "reads one line into var (a number if it is one, else a string)"},
    {"and", "a and b", "logical and (also `&&`), short-circuit"},
    {"or", "a or b", "logical or (also `||`), short-circuit"},
    {"not", "not a", "logical not (also `!`); binds tight: `not a = b` is `(not a) = b`"},
    {"mod", "a mod b", "remainder (also `%`)"},
    {"rem", "rem text", "a comment to the end of the line (also `//` and `'`)"},
};

const KeywordHelp* keywordHelp(std::string_view word) {
  std::string w = lower(word);
  for (const KeywordHelp& k : kKeywords)
    if (k.word == w) return &k;
  return nullptr;
}

std::string keywordDoc(const KeywordHelp& k) {
  std::string s = "```robotbasic\n";
  s += k.usage;
  s += "\n```\n";
  s += k.help;
  s += "\n\n*keyword*";
  return s;
}

/// The parameter names of a signature with their byte offsets in `label` (which contains the
/// signature at `offset`): "x, y [, heading]" -> x, y, heading.
json parameterLabels(std::string_view sig, size_t offset) {
  json params = json::array();
  size_t i = 0;
  while (i < sig.size()) {
    char c = sig[i];
    if (c == '&' || std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      size_t b = i;
      ++i;
      while (i < sig.size() && isNameChar(sig[i])) ++i;
      while (i < sig.size() && sig[i] == '.') ++i;  // "items..."
      params.push_back({{"label", {offset + b, offset + i}}});
    } else {
      ++i;
    }
  }
  return params;
}

/// True when the end of `before` (the start of a line) is inside a string or a comment.
bool inStringOrComment(std::string_view before) {
  bool inString = false;
  for (size_t i = 0; i < before.size(); ++i) {
    char c = before[i];
    if (c == '"') inString = !inString;
    else if (!inString && (c == '\'' || (c == '/' && i + 1 < before.size() && before[i + 1] == '/')))
      return true;
    else if (!inString && (c == 'r' || c == 'R') && (i == 0 || !isNameChar(before[i - 1])) &&
             i + 3 <= before.size() && lower(before.substr(i, 3)) == "rem" &&
             (i + 3 == before.size() ? false : !isNameChar(before[i + 3])))
      return true;  // `rem` starts a comment anywhere
  }
  return inString;
}

/// What the text before the cursor says about the name being typed.
enum class Place { Nowhere, Statement, Expression, Label, SubName };

Place placeBefore(std::string_view before) {
  if (inStringOrComment(before)) return Place::Nowhere;  // no completion in strings and comments
  size_t end = before.find_last_not_of(" \t");
  if (end == std::string_view::npos) return Place::Statement;
  std::string_view trimmed = before.substr(0, end + 1);
  if (trimmed.back() == ':') {
    // A label ("Top:") before a statement.
    std::string_view lbl = trimmed.substr(0, trimmed.size() - 1);
    size_t b = lbl.find_first_not_of(" \t");
    bool allName = b != std::string_view::npos;
    for (size_t i = b; allName && i < lbl.size(); ++i) allName = isNameChar(lbl[i]);
    return allName ? Place::Statement : Place::Expression;
  }
  if (!isNameChar(trimmed.back())) return Place::Expression;
  size_t b = trimmed.size();
  while (b > 0 && isNameChar(trimmed[b - 1])) --b;
  std::string prev = lower(trimmed.substr(b));
  if (prev == "goto" || prev == "gosub") return Place::Label;
  if (prev == "call") return Place::SubName;
  if (prev == "sub") return Place::Nowhere;
  if (prev == "then" || prev == "else") return Place::Statement;
  if (b > 0 && trimmed[b - 1] == '#') return Place::Nowhere;
  return Place::Expression;
}

}  // namespace

// ---- the reader that serves open documents before the disk

class Server::Reader : public SourceReader {
 public:
  explicit Reader(Server& server) : server_(server) {}

  std::optional<std::string> find(const std::string& path) override {
    std::string normal = std::filesystem::path(path).lexically_normal().string();
    for (const auto& [uri, doc] : server_.docs_)
      if (doc.path == normal) return normal;
    return server_.disk_.find(path);
  }
  std::optional<std::string> read(const std::string& canonical) override {
    for (const auto& [uri, doc] : server_.docs_)
      if (doc.path == canonical) return doc.text;
    return server_.disk_.read(canonical);
  }

 private:
  Server& server_;
};

Server::Server(std::ostream& out, SourceReader& disk, const BuiltinTable& builtins,
               ServerOptions options)
    : out_(out), disk_(disk), builtins_(builtins), options_(std::move(options)),
      reader_(std::make_unique<Reader>(*this)) {}

Server::~Server() = default;

int Server::run(std::istream& in) {
  MessageReader reader(in, options_.maxMessageBytes ? options_.maxMessageBytes : kMaxMessageBytes);
  while (!exited_) {
    MessageReader::Result r = reader.next();
    if (r.status == MessageReader::Status::End) break;
    if (r.status != MessageReader::Status::Ok) {
      replyError(nullptr, r.status == MessageReader::Status::TooLarge ? kInvalidRequest : kParseError,
                 "rb lsp: ignored " + r.why);
      continue;
    }
    handle(r.body);
  }
  return exitCode();
}

// ---- messages

namespace {

/// The deepest nesting of arrays and objects in a JSON text (strings skipped). Copying and
/// destroying a parsed value recurses, so a message nested a million deep must be refused
/// before it is parsed.
size_t nestingDepth(std::string_view text) {
  size_t depth = 0, deepest = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

constexpr size_t kMaxNesting = 200;

}  // namespace

void Server::handle(const std::string& body) {
  if (nestingDepth(body) > kMaxNesting) {
    replyError(nullptr, kInvalidRequest,
               "rb lsp: the message is nested more than " + std::to_string(kMaxNesting) + " levels deep");
    return;
  }
  json msg = json::parse(body, nullptr, false);
  if (msg.is_discarded()) {
    replyError(nullptr, kParseError, "rb lsp: the message is not valid JSON");
    return;
  }
  if (!msg.is_object()) {
    replyError(nullptr, kInvalidRequest,
               msg.is_array() ? "rb lsp: batches are not supported" : "rb lsp: a message must be an object");
    return;
  }
  dispatch(msg);
}

void Server::dispatch(const json& msg) {
  auto methodIt = msg.find("method");
  auto idIt = msg.find("id");
  bool hasId = idIt != msg.end() && (idIt->is_number_integer() || idIt->is_string());
  json id = hasId ? *idIt : json(nullptr);
  if (methodIt == msg.end() || !methodIt->is_string()) {
    // A response to a request of ours (we send none that need answers), or garbage.
    if (idIt == msg.end()) replyError(nullptr, kInvalidRequest, "rb lsp: a message without a method");
    return;
  }
  const std::string method = *methodIt;
  if (idIt != msg.end() && !hasId) {
    replyError(nullptr, kInvalidRequest, "rb lsp: a request id must be a number or a string");
    return;
  }
  json params = msg.value("params", json::object());
  bool isRequest = hasId;

  if (method == "exit") {
    exited_ = true;
    return;
  }
  if (!initialized_ && method != "initialize") {
    if (isRequest) replyError(id, kServerNotInitialized, "rb lsp: the server is not initialized yet");
    return;
  }
  if (shutdown_) {
    if (isRequest) replyError(id, kInvalidRequest, "rb lsp: the server is shutting down");
    return;
  }

  try {
    if (isRequest) {
      if (method == "initialize") {
        if (initialized_) replyError(id, kInvalidRequest, "rb lsp: initialize was already received");
        else reply(id, initialize(params));
      } else if (method == "shutdown") {
        shutdown_ = true;
        reply(id, nullptr);
      } else if (method == "textDocument/hover") {
        reply(id, hover(params));
      } else if (method == "textDocument/completion") {
        reply(id, completion(params));
      } else if (method == "textDocument/signatureHelp") {
        reply(id, signatureHelp(params));
      } else if (method == "textDocument/definition") {
        reply(id, definition(params));
      } else if (method == "textDocument/documentSymbol") {
        reply(id, documentSymbol(params));
      } else if (method == "textDocument/codeLens") {
        reply(id, codeLens(params));
      } else {
        replyError(id, kMethodNotFound, "rb lsp: unknown method '" + method + "'");
      }
      return;
    }
    if (method == "initialized" || method == "$/cancelRequest" || method == "$/setTrace") return;
    if (method == "textDocument/didOpen") didOpen(params);
    else if (method == "textDocument/didChange") didChange(params);
    else if (method == "textDocument/didClose") didClose(params);
    else if (method == "textDocument/didSave") {
      if (Document* doc = document(params)) fileChanged(doc->path);
    } else if (method == "workspace/didChangeConfiguration") {
      if (configure(params.value("settings", json::object())))
        for (auto& [uri, doc] : docs_) check(doc);
    } else if (method == "workspace/didChangeWatchedFiles") {
      for (const json& change : params.at("changes")) fileChanged(uriToPath(change.at("uri").get<std::string>()));
    }
    // Other notifications are ignored, as the protocol asks.
  } catch (const json::exception& e) {
    if (isRequest) replyError(id, kInvalidParams, std::string("rb lsp: bad parameters: ") + e.what());
  } catch (const std::exception& e) {
    if (isRequest) replyError(id, kInternalError, std::string("rb lsp: ") + e.what());
  }
}

void Server::reply(const json& id, json result) {
  json msg = {{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}};
  writeMessage(out_, msg.dump(-1, ' ', false, json::error_handler_t::replace));
}

void Server::replyError(const json& id, int code, const std::string& message) {
  json msg = {{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}};
  writeMessage(out_, msg.dump(-1, ' ', false, json::error_handler_t::replace));
}

void Server::notify(const std::string& method, json params) {
  json msg = {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}};
  writeMessage(out_, msg.dump(-1, ' ', false, json::error_handler_t::replace));
}

// ---- lifecycle

json Server::initialize(const json& params) {
  const json caps = params.value("capabilities", json::object());
  if (caps.contains("general") && caps["general"].contains("positionEncodings")) {
    for (const json& e : caps["general"]["positionEncodings"])
      if (e == "utf-8") encoding_ = Encoding::Utf8;
  }
  configure(params.value("initializationOptions", json::object()));
  if (caps.contains("textDocument") && caps["textDocument"].contains("documentSymbol"))
    hierarchicalSymbols_ =
        caps["textDocument"]["documentSymbol"].value("hierarchicalDocumentSymbolSupport", false);
  json capabilities = {
      {"positionEncoding", encoding_ == Encoding::Utf8 ? "utf-8" : "utf-16"},
      {"textDocumentSync", {{"openClose", true}, {"change", kFullSync}, {"save", {{"includeText", false}}}}},
      {"hoverProvider", true},
      {"completionProvider", {{"triggerCharacters", json::array()}, {"resolveProvider", false}}},
      {"signatureHelpProvider", {{"triggerCharacters", {"(", ",", " "}}}},
      {"definitionProvider", true},
      {"documentSymbolProvider", true},
      {"codeLensProvider", {{"resolveProvider", false}}},
  };
  initialized_ = true;  // only once the parameters were understood: a client may try again
  return {{"capabilities", capabilities}, {"serverInfo", {{"name", "rb"}, {"version", options_.version}}}};
}

bool Server::configure(const json& settings) {
  // {"rb": {"portable": true}} as VS Code sends its section, or {"portable": true}.
  const json* rb = &settings;
  if (settings.is_object() && settings.contains("rb") && settings["rb"].is_object()) rb = &settings["rb"];
  if (!rb->is_object() || !rb->contains("portable") || !(*rb)["portable"].is_boolean()) return false;
  bool portable = (*rb)["portable"].get<bool>();
  if (portable == portable_) return false;
  portable_ = portable;
  return true;
}

// ---- documents

Server::Document* Server::document(const json& params) {
  std::string uri = params.at("textDocument").at("uri").get<std::string>();
  auto it = docs_.find(uri);
  return it == docs_.end() ? nullptr : &it->second;
}

void Server::didOpen(const json& params) {
  const json& td = params.at("textDocument");
  std::string uri = td.at("uri").get<std::string>();
  std::string text = td.at("text").get<std::string>();
  int64_t version = td.value("version", int64_t{0});
  Document& doc = docs_[uri];
  doc.uri = uri;
  doc.path = uriToPath(uri);
  if (!doc.path.empty() && doc.path.front() == '/')
    doc.path = std::filesystem::path(doc.path).lexically_normal().string();
  doc.text = std::move(text);
  doc.version = version;
  check(doc);
  fileChanged(doc.path);
}

void Server::didChange(const json& params) {
  Document* doc = document(params);
  if (!doc) return;
  int64_t version = params.at("textDocument").value("version", doc->version);
  std::optional<std::string> text;
  for (const json& change : params.at("contentChanges")) {
    // Full sync: every change is the whole text (a ranged change would mean the client ignored
    // the sync kind we asked for; its text is then not the document, so it is skipped).
    if (change.contains("range")) continue;
    text = change.at("text").get<std::string>();
  }
  if (text) doc->text = std::move(*text);
  doc->version = version;
  check(*doc);
  fileChanged(doc->path);
}

void Server::didClose(const json& params) {
  Document* doc = document(params);
  if (!doc) return;
  std::string uri = doc->uri, path = doc->path;
  docs_.erase(uri);
  notify("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", json::array()}});
  fileChanged(path);
}

void Server::fileChanged(const std::string& path) {
  for (auto& [uri, doc] : docs_) {
    if (doc.path == path || !doc.analysis) continue;
    const auto& inc = doc.analysis->includes;
    if (std::find(inc.begin(), inc.end(), path) != inc.end()) check(doc);
  }
}

void Server::check(Document& doc) {
  doc.analysis = analyze(doc.path, doc.text, *reader_, builtins_, options_.load, portable_);
  publish(doc);
}

json Server::range(const Analysis& a, SourceLoc loc) const {
  json zero = {{"line", 0}, {"character", 0}};
  if (!loc.valid() || loc.file >= a.program->sources.size()) return {{"start", zero}, {"end", zero}};
  std::string_view line = a.program->sources.file(loc.file).lineText(loc.line);
  size_t b = std::min<size_t>(loc.col > 0 ? loc.col - 1 : 0, line.size());
  size_t e = b;
  if (e < line.size() && line[e] == '"') {
    size_t close = line.find('"', e + 1);
    e = close == std::string_view::npos ? line.size() : close + 1;
  } else {
    while (e < line.size() && isNameChar(line[e])) ++e;
    if (e == b && e < line.size()) ++e;
  }
  uint32_t l = loc.line - 1;
  return {{"start", {{"line", l}, {"character", toLspCharacter(line, b, encoding_)}}},
          {"end", {{"line", l}, {"character", toLspCharacter(line, e, encoding_)}}}};
}

json Server::location(const Analysis& a, SourceLoc loc) const {
  std::string name = loc.file < a.program->sources.size() ? a.program->sources.file(loc.file).name() : "";
  std::string uri;
  // The document's own file keeps the URI the editor gave it.
  for (const auto& [u, doc] : docs_)
    if (doc.analysis.get() == &a && loc.file == 0) uri = u;
  if (uri.empty()) uri = pathToUri(name);
  return {{"uri", uri}, {"range", range(a, loc)}};
}

void Server::publish(const Document& doc) {
  const Analysis& a = *doc.analysis;
  json list = json::array();
  for (const Diagnostic& d : a.diags.all()) {
    if (d.severity == Severity::Note) {
      // A note belongs to the diagnostic before it.
      if (!list.empty()) {
        json& last = list.back();
        last["message"] = last["message"].get<std::string>() + "\nnote: " + d.message;
        if (d.loc.valid())
          last["relatedInformation"].push_back({{"location", location(a, d.loc)}, {"message", d.message}});
      }
      continue;
    }
    json item = {{"severity", d.severity == Severity::Error ? kSeverityError : kSeverityWarning},
                 {"source", "rb"},
                 {"message", d.message}};
    // The rule code, so that editors show it and users can look it up (docs/diagnostics.md).
    if (!d.code.empty()) {
      item["code"] = d.code;
      if (findRule(d.code)) item["codeDescription"] = {{"href", ruleUrl(d.code)}};
    }
    if (d.loc.file == 0 || !d.loc.valid()) {
      item["range"] = range(a, d.loc);
    } else {
      // A diagnostic in an included file is shown on the #include line that brought it in.
      SourceLoc at = d.loc.file < a.includedAt.size() ? a.includedAt[d.loc.file] : SourceLoc{};
      const SourceFile& f = a.program->sources.file(d.loc.file);
      std::string base = std::filesystem::path(f.name()).filename().string();
      item["message"] = "in included file '" + base + "', line " + std::to_string(d.loc.line) + ": " + d.message;
      item["range"] = range(a, at.valid() ? at : SourceLoc{});
      if (at.valid()) {
        std::string_view line = a.program->sources.file(0).lineText(at.line);
        item["range"]["end"]["character"] = toLspCharacter(line, line.size(), encoding_);
      }
      item["relatedInformation"] = json::array({{{"location", location(a, d.loc)}, {"message", d.message}}});
    }
    list.push_back(std::move(item));
  }
  notify("textDocument/publishDiagnostics",
         {{"uri", doc.uri}, {"version", doc.version}, {"diagnostics", std::move(list)}});
}

// ---- features

std::string Server::ruleHelpAt(const Analysis& a, uint32_t line, size_t byteCol) const {
  std::string out;
  for (const Diagnostic& d : a.diags.all()) {
    if (d.severity == Severity::Note || d.code.empty() || d.loc.file != 0 || d.loc.line != line) continue;
    auto [first, last] = diagnosticColumns(a.program->sources, d);
    if (byteCol < first || byteCol > last) continue;
    const Rule* rule = findRule(d.code);
    if (!rule || out.find(d.code) != std::string::npos) continue;
    if (!out.empty()) out += "\n\n";
    out += "**" + std::string(rule->id) + "** (" + severityName(rule->severity) + "): " + ruleMarkdown(*rule) +
           " [More](" + ruleUrl(rule->id) + ")";
  }
  return out;
}

json Server::hover(const json& params) {
  Document* doc = document(params);
  if (!doc || !doc->analysis) return nullptr;
  const json& pos = params.at("position");
  std::string_view line = lineOf(doc->text, pos.at("line").get<uint32_t>());
  size_t col = toByteColumn(line, pos.at("character").get<uint32_t>(), encoding_);
  // Over a diagnostic: what its rule means, from the one table of rules.
  std::string about = ruleHelpAt(*doc->analysis, pos.at("line").get<uint32_t>() + 1, col + 1);
  Span span = nameAt(line, col);
  if (span.empty() || inStringOrComment(line.substr(0, span.begin))) {
    if (about.empty()) return nullptr;
    return {{"contents", {{"kind", "markdown"}, {"value", about}}}};
  }
  std::string word(line.substr(span.begin, span.end - span.begin));
  const Analysis& a = *doc->analysis;
  std::string text;
  for (const Symbol& s : a.symbols) {
    if (s.name != word) continue;
    std::string where = a.program->sources.file(s.loc.file).name();
    where = std::filesystem::path(where).filename().string() + ", line " + std::to_string(s.loc.line);
    text = "```robotbasic\n";
    text += s.signature();
    text += "\n```\n";
    text += s.kind == Symbol::Kind::Sub ? "sub" : "label";
    text += " defined in ";
    text += where;
    break;
  }
  if (text.empty()) {
    for (BuiltinKind k : {BuiltinKind::Command, BuiltinKind::Function, BuiltinKind::Constant}) {
      const Builtin* b = builtins_.find(word, k);
      if (!b) continue;
      if (!text.empty()) text += "\n\n---\n\n";
      text += builtinDoc(*b);
    }
  }
  if (text.empty()) {
    if (const KeywordHelp* k = keywordHelp(word)) text = keywordDoc(*k);
  }
  if (text.empty()) {
    auto v = a.variables.find(word);
    if (v != a.variables.end()) text = "```robotbasic\n" + word + "\n```\nvariable (names are case-sensitive)";
  }
  if (!about.empty()) text = text.empty() ? about : about + "\n\n---\n\n" + text;
  if (text.empty()) return nullptr;
  uint32_t l = pos.at("line").get<uint32_t>();
  return {{"contents", {{"kind", "markdown"}, {"value", text}}},
          {"range", {{"start", {{"line", l}, {"character", toLspCharacter(line, span.begin, encoding_)}}},
                     {"end", {{"line", l}, {"character", toLspCharacter(line, span.end, encoding_)}}}}}};
}

json Server::completion(const json& params) {
  json items = json::array();
  Document* doc = document(params);
  if (!doc || !doc->analysis) return items;
  const json& pos = params.at("position");
  uint32_t lineNo = pos.at("line").get<uint32_t>();
  std::string_view line = lineOf(doc->text, lineNo);
  size_t col = toByteColumn(line, pos.at("character").get<uint32_t>(), encoding_);
  size_t b = col;
  while (b > 0 && isNameChar(line[b - 1])) --b;
  Place place = placeBefore(line.substr(0, b));
  if (place == Place::Nowhere) return items;
  const Analysis& a = *doc->analysis;
  std::set<std::string> seen;
  auto add = [&](const std::string& label, int kind, const std::string& detail, const std::string& docs) {
    if (!seen.insert(label).second) return;
    json item = {{"label", label}, {"kind", kind}};
    if (!detail.empty()) item["detail"] = detail;
    if (!docs.empty()) item["documentation"] = {{"kind", "markdown"}, {"value", docs}};
    items.push_back(std::move(item));
  };
  auto addSymbols = [&](Symbol::Kind kind) {
    for (const Symbol& s : a.symbols)
      if (s.kind == kind)
        add(s.name, kind == Symbol::Kind::Sub ? kItemFunction : kItemReference, s.signature(), "");
  };
  if (place == Place::Label) {
    addSymbols(Symbol::Kind::Label);
    return items;
  }
  if (place == Place::SubName) {
    addSymbols(Symbol::Kind::Sub);
    return items;
  }
  bool statement = place == Place::Statement;
  for (const Builtin& bi : builtins_.rows()) {
    bool fits = bi.kind == BuiltinKind::Command ? statement : !statement;
    if (!fits) continue;
    add(std::string(bi.name), bi.kind == BuiltinKind::Constant ? kItemConstant : kItemFunction, usageOf(bi),
        std::string(bi.help));
  }
  static const std::set<std::string_view> kStatementWords = {
      "if", "else", "elseif", "endif", "end", "for", "next", "while", "wend", "repeat", "until",
      "break", "continue", "goto", "gosub", "return", "sub", "endsub", "call", "dim", "data",
      "print", "input", "rem"};
  for (std::string_view kw : keywordSpellings()) {
    if (statement != (kStatementWords.count(kw) > 0)) continue;
    const KeywordHelp* k = keywordHelp(kw);
    add(std::string(kw), kItemKeyword, "keyword", k ? keywordDoc(*k) : "");
  }
  addSymbols(Symbol::Kind::Sub);
  // Variables of the scope the cursor is in (a sub's locals in a sub, the main program's
  // outside), and arrays, which are global.
  int scope = a.scopeAt(lineNo + 1);
  for (const auto& [name, uses] : a.variables) {
    bool array = a.arrays.count(name) > 0;
    bool inScope = false;
    for (const Analysis::Use& u : uses) {
      // The name being typed is a "variable" of the text as it stands: it does not count.
      bool typing = u.loc.file == 0 && u.loc.line == lineNo + 1 && u.loc.col == b + 1;
      if (!typing && (array || u.scope == scope)) inScope = true;
    }
    if (inScope) add(name, kItemVariable, array ? "array" : "variable", "");
  }
  return items;
}

json Server::signatureHelp(const json& params) {
  Document* doc = document(params);
  if (!doc || !doc->analysis) return nullptr;
  const json& pos = params.at("position");
  std::string_view line = lineOf(doc->text, pos.at("line").get<uint32_t>());
  size_t col = toByteColumn(line, pos.at("character").get<uint32_t>(), encoding_);
  std::string_view before = line.substr(0, col);
  // Innermost open parenthesis, and commas after it, outside strings.
  std::vector<std::pair<size_t, int>> open;  // position of '(' and commas seen inside it
  int topCommas = 0;
  bool inString = false;
  for (size_t i = 0; i < before.size(); ++i) {
    char c = before[i];
    if (c == '"') inString = !inString;
    if (inString) continue;
    if (c == '\'' || (c == '/' && i + 1 < before.size() && before[i + 1] == '/')) return nullptr;
    if (c == '(') open.push_back({i, 0});
    else if (c == ')' && !open.empty()) open.pop_back();
    else if (c == ',') (open.empty() ? topCommas : open.back().second)++;
  }
  if (inString) return nullptr;
  std::string name;
  int active = 0;
  bool command = false;
  if (!open.empty()) {
    size_t p = open.back().first;
    while (p > 0 && (before[p - 1] == ' ' || before[p - 1] == '\t')) --p;
    size_t e = p;
    while (p > 0 && isNameChar(before[p - 1])) --p;
    name = std::string(before.substr(p, e - p));
    active = open.back().second;
  } else {
    // A command's arguments: the first word of the statement (after a label).
    size_t p = before.find_first_not_of(" \t");
    if (p == std::string_view::npos) return nullptr;
    size_t e = p;
    while (e < before.size() && isNameChar(before[e])) ++e;
    if (e < before.size() && before[e] == ':') {
      p = before.find_first_not_of(" \t", e + 1);
      if (p == std::string_view::npos) return nullptr;
      e = p;
      while (e < before.size() && isNameChar(before[e])) ++e;
    }
    if (e >= before.size() || e == p) return nullptr;  // still typing the command's name
    name = std::string(before.substr(p, e - p));
    active = topCommas;
    command = true;
  }
  if (name.empty()) return nullptr;
  json sig;
  const Builtin* b = command ? builtins_.find(name, BuiltinKind::Command) : builtins_.find(name, BuiltinKind::Function);
  if (!b && !command) b = builtins_.find(name, BuiltinKind::Command);  // print(x), rForward(10)
  if (b) {
    std::string label = usageOf(*b);
    size_t offset = b->name.size() + 1;
    if (b->kind == BuiltinKind::Command && command == false) {
      label = std::string(b->name);
      label += '(';
      label += b->signature;
      label += ')';
    }
    sig = {{"label", label}, {"documentation", {{"kind", "markdown"}, {"value", std::string(b->help)}}},
           {"parameters", parameterLabels(b->signature, offset)}};
  } else {
    for (const Symbol& s : doc->analysis->symbols) {
      if (s.kind != Symbol::Kind::Sub || s.name != name) continue;
      std::string label = s.name + "(";
      json ps = json::array();
      for (size_t i = 0; i < s.params.size(); ++i) {
        if (i) label += ", ";
        ps.push_back({{"label", {label.size(), label.size() + s.params[i].size()}}});
        label += s.params[i];
      }
      label += ")";
      sig = {{"label", label}, {"parameters", ps}};
      break;
    }
  }
  if (sig.is_null()) return nullptr;
  int n = static_cast<int>(sig["parameters"].size());
  if (n > 0 && active >= n) active = n - 1;
  return {{"signatures", json::array({sig})}, {"activeSignature", 0}, {"activeParameter", active}};
}

json Server::definition(const json& params) {
  Document* doc = document(params);
  if (!doc || !doc->analysis) return nullptr;
  const json& pos = params.at("position");
  std::string_view line = lineOf(doc->text, pos.at("line").get<uint32_t>());
  size_t col = toByteColumn(line, pos.at("character").get<uint32_t>(), encoding_);
  Span span = nameAt(line, col);
  if (span.empty() || inStringOrComment(line.substr(0, span.begin))) return nullptr;
  std::string word(line.substr(span.begin, span.end - span.begin));
  json out = json::array();
  for (const Symbol& s : doc->analysis->symbols)
    if (s.name == word) out.push_back(location(*doc->analysis, s.loc));
  if (out.empty()) return nullptr;
  return out;
}

json Server::documentSymbol(const json& params) {
  Document* doc = document(params);
  json out = json::array();
  if (!doc || !doc->analysis) return out;
  const Analysis& a = *doc->analysis;
  if (!hierarchicalSymbols_) {
    for (const Symbol& s : a.symbols) {
      if (s.loc.file != 0) continue;
      json item = {{"name", s.name},
                   {"kind", s.kind == Symbol::Kind::Sub ? kSymbolFunction : kSymbolKey},
                   {"location", location(a, s.loc)}};
      if (s.container >= 0) item["containerName"] = a.symbols[static_cast<size_t>(s.container)].name;
      out.push_back(std::move(item));
    }
    return out;
  }
  std::map<int, size_t> subSlot;  // symbol index -> position in out
  for (size_t i = 0; i < a.symbols.size(); ++i) {
    const Symbol& s = a.symbols[i];
    if (s.loc.file != 0) continue;
    json sel = range(a, s.loc);
    json full = sel;
    if (s.kind == Symbol::Kind::Sub) {
      full["start"]["character"] = 0;
      json endRange = range(a, s.end);
      std::string_view endLine = a.program->sources.file(0).lineText(s.end.line);
      full["end"] = {{"line", endRange["end"]["line"]},
                     {"character", toLspCharacter(endLine, endLine.size(), encoding_)}};
    }
    json item = {{"name", s.name},
                 {"detail", s.signature()},
                 {"kind", s.kind == Symbol::Kind::Sub ? kSymbolFunction : kSymbolKey},
                 {"range", full},
                 {"selectionRange", sel},
                 {"children", json::array()}};
    auto slot = subSlot.find(s.container);
    if (s.container >= 0 && slot != subSlot.end()) {
      out[slot->second]["children"].push_back(std::move(item));
    } else {
      if (s.kind == Symbol::Kind::Sub) subSlot[static_cast<int>(i)] = out.size();
      out.push_back(std::move(item));
    }
  }
  return out;
}

json Server::codeLens(const json& params) {
  Document* doc = document(params);
  json out = json::array();
  if (!doc || doc->uri.rfind("file:", 0) != 0) return out;
  json zero = {{"line", 0}, {"character", 0}};
  out.push_back({{"range", {{"start", zero}, {"end", zero}}},
                 {"command", {{"title", "Run with rb"}, {"command", kRunCommand}, {"arguments", {doc->uri}}}}});
  return out;
}

}  // namespace rb::lsp
