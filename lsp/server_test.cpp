#include "server.h"

#include "base/rules.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "lang/token.h"
#include "machine/builtins.h"
#include "transport.h"

using json = nlohmann::json;

namespace {

/// Files on a pretend disk.
class MemoryDisk : public rb::SourceReader {
 public:
  std::map<std::string, std::string> files;
  std::optional<std::string> find(const std::string& path) override {
    std::string normal = std::filesystem::path(path).lexically_normal().string();
    if (files.count(normal)) return normal;
    return std::nullopt;
  }
  std::optional<std::string> read(const std::string& canonical) override {
    auto it = files.find(canonical);
    if (it == files.end()) return std::nullopt;
    return it->second;
  }
};

std::vector<json> parseAll(const std::string& text) {
  std::istringstream in(text);
  rb::lsp::MessageReader reader(in);
  std::vector<json> out;
  for (;;) {
    auto r = reader.next();
    if (r.status == rb::lsp::MessageReader::Status::End) break;
    REQUIRE(r.status == rb::lsp::MessageReader::Status::Ok);
    out.push_back(json::parse(r.body));
  }
  return out;
}

class Session {
 public:
  MemoryDisk disk;
  std::ostringstream out;
  rb::lsp::Server server{out, disk, rb::standardBuiltins(), {}};
  int nextId = 1;

  /// Sends a raw body; returns every message the server wrote in answer.
  std::vector<json> sendRaw(const std::string& body) {
    out.str("");
    server.handle(body);
    return parseAll(out.str());
  }
  std::vector<json> notify(const std::string& method, json params) {
    return sendRaw(json{{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}}.dump());
  }
  /// Sends a request and returns its response (other messages are dropped).
  json request(const std::string& method, json params = json::object()) {
    int id = nextId++;
    for (json& m : sendRaw(json{{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}}.dump()))
      if (m.contains("id") && m["id"] == id) return m;
    FAIL("no response to " << method);
    return nullptr;
  }
  json initialize(json caps = json::object()) {
    json r = request("initialize", {{"processId", nullptr}, {"rootUri", nullptr}, {"capabilities", caps}});
    notify("initialized", json::object());
    return r;
  }
  /// Opens a document; returns the diagnostics published for it.
  json open(const std::string& uri, const std::string& text) {
    json diags;
    for (json& m : notify("textDocument/didOpen",
                          {{"textDocument", {{"uri", uri}, {"languageId", "robotbasic"}, {"version", 1}, {"text", text}}}}))
      if (m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri) diags = m["params"]["diagnostics"];
    return diags;
  }
  json at(const std::string& method, const std::string& uri, int line, int character, json extra = json::object()) {
    json params = {{"textDocument", {{"uri", uri}}}, {"position", {{"line", line}, {"character", character}}}};
    params.update(extra);
    return request(method, params);
  }
};

const std::string kUri = "file:///work/p/main.bas";

bool hasLabel(const json& items, const std::string& label) {
  for (const json& i : items)
    if (i["label"] == label) return true;
  return false;
}

}  // namespace

TEST_CASE("lsp: requests before initialize are refused, notifications dropped", "[lsp]") {
  Session s;
  json r = s.at("textDocument/hover", kUri, 0, 0);
  CHECK(r["error"]["code"] == -32002);
  CHECK(s.notify("textDocument/didOpen", {{"textDocument", {{"uri", kUri}, {"text", "x"}}}}).empty());
}

TEST_CASE("lsp: initialize announces the features", "[lsp]") {
  Session s;
  CHECK(s.request("initialize", {{"capabilities", {{"textDocument", {{"documentSymbol", 5}}}}}})["error"]["code"] == -32602);  // may be tried again
  json r = s.initialize();
  json caps = r["result"]["capabilities"];
  CHECK(caps["textDocumentSync"]["change"] == 1);
  CHECK(caps["hoverProvider"] == true);
  CHECK(caps["definitionProvider"] == true);
  CHECK(caps["documentSymbolProvider"] == true);
  CHECK(caps["completionProvider"].is_object());
  CHECK(caps["signatureHelpProvider"]["triggerCharacters"].size() > 0);
  CHECK(caps["positionEncoding"] == "utf-16");
  CHECK(r["result"]["serverInfo"]["name"] == "rb");
  CHECK(s.request("initialize")["error"]["code"] == -32600);  // only once
}

TEST_CASE("lsp: utf-8 positions when the client offers them", "[lsp]") {
  Session s;
  json r = s.initialize({{"general", {{"positionEncodings", {"utf-16", "utf-8"}}}}});
  CHECK(r["result"]["capabilities"]["positionEncoding"] == "utf-8");
}

TEST_CASE("lsp: bad messages get error replies and the server goes on", "[lsp]") {
  Session s;
  s.initialize();
  auto replies = s.sendRaw("{not json");
  REQUIRE(replies.size() == 1);
  CHECK(replies[0]["error"]["code"] == -32700);
  CHECK(replies[0]["id"].is_null());
  replies = s.sendRaw("[1, 2]");
  REQUIRE(replies.size() == 1);
  CHECK(replies[0]["error"]["code"] == -32600);
  replies = s.sendRaw("42");
  REQUIRE(replies.size() == 1);
  CHECK(replies[0]["error"]["code"] == -32600);
  // Nested a million deep: refused before parsing (copying it would overflow the stack).
  replies = s.sendRaw(R"({"jsonrpc":"2.0","id":9,"method":"x","params":)" + std::string(1000000, '[') +
                      std::string(1000000, ']') + "}");
  REQUIRE(replies.size() == 1);
  CHECK(replies[0]["error"]["code"] == -32600);
  // Brackets inside strings do not count.
  CHECK(s.request("workspace/nothing", {{"text", std::string(1000, '[')}})["error"]["code"] == -32601);
  CHECK(s.request("workspace/symbolz")["error"]["code"] == -32601);
  CHECK(s.sendRaw(R"({"jsonrpc":"2.0","method":"$/unknownNotification","params":{}})").empty());
  // Parameters of the wrong shape: InvalidParams, not a crash.
  CHECK(s.request("textDocument/hover", {{"textDocument", 5}})["error"]["code"] == -32602);
  s.open(kUri, "print 1\n");
  CHECK(s.request("textDocument/hover", {{"textDocument", {{"uri", kUri}}}, {"position", "x"}})["error"]["code"] == -32602);
  CHECK(s.request("textDocument/completion", {{"textDocument", {{"uri", kUri}}}})["error"]["code"] == -32602);
  CHECK(s.notify("textDocument/didOpen", {{"textDocument", {{"uri", 3}}}}).empty());
  // Still answering.
  CHECK(s.request("shutdown")["result"].is_null());
}

TEST_CASE("lsp: diagnostics as rb check gives them, with ranges", "[lsp]") {
  Session s;
  s.initialize();
  json d = s.open(kUri, "x = 1\nrForwrd 10\nprint x\n");
  REQUIRE(d.size() == 1);
  CHECK(d[0]["severity"] == 1);
  CHECK(d[0]["source"] == "rb");
  CHECK(d[0]["range"]["start"]["line"] == 1);
  CHECK(d[0]["range"]["start"]["character"] == 0);
  CHECK(d[0]["range"]["end"]["character"] == 7);
  CHECK(d[0]["message"].get<std::string>().find("rForward") != std::string::npos);

  // A warning (read but never assigned), after a full-text change.
  std::vector<json> out = s.notify("textDocument/didChange",
      {{"textDocument", {{"uri", kUri}, {"version", 2}}}, {"contentChanges", {{{"text", "Real = 1\nprint real\n"}}}}});
  REQUIRE(out.size() == 1);
  CHECK(out[0]["params"]["version"] == 2);
  json w = out[0]["params"]["diagnostics"];
  REQUIRE(w.size() == 1);
  CHECK(w[0]["severity"] == 2);
  CHECK(w[0]["range"]["start"] == json{{"line", 1}, {"character", 6}});

  // Closing clears them.
  out = s.notify("textDocument/didClose", {{"textDocument", {{"uri", kUri}}}});
  REQUIRE(out.size() == 1);
  CHECK(out[0]["params"]["diagnostics"].empty());
}

TEST_CASE("lsp: a diagnostic links to its rule, and hover over it says what the rule means", "[lsp]") {
  Session s;
  s.initialize();
  json d = s.open(kUri, "x = 1\nrForwrd 10\nprint x\n");
  REQUIRE(d.size() == 1);
  CHECK(d[0]["code"] == "rb-unknown-command");
  std::string href = d[0]["codeDescription"]["href"];
  CHECK(href.ends_with("/diagnostics.md#rb-unknown-command"));
  CHECK(href.starts_with("https://"));
  // Over the misspelt command: the rule's full description from the rule table.
  std::string text = s.at("textDocument/hover", kUri, 1, 3)["result"]["contents"]["value"];
  CHECK(text.find("**rb-unknown-command** (error)") != std::string::npos);
  CHECK(text.find(std::string(rb::findRule("rb-unknown-command")->description.substr(0, 20))) != std::string::npos);
  // Elsewhere, none.
  text = s.at("textDocument/hover", kUri, 2, 1)["result"]["contents"]["value"];
  CHECK(text.find("rb-unknown-command") == std::string::npos);
}

TEST_CASE("lsp: two values side by side, the missing operator as rb check gives it", "[lsp]") {
  Session s;
  s.initialize();
  json d = s.open(kUri, "n = 5\nprint \"moves: \" n\n");
  REQUIRE(d.size() == 1);
  CHECK(d[0]["code"] == "rb-missing-operator");
  CHECK(d[0]["message"] == "missing '+' between \"moves: \" and 'n'");
  CHECK(d[0]["range"]["start"] == json{{"line", 1}, {"character", 16}});
  CHECK(d[0]["codeDescription"]["href"].get<std::string>().ends_with("/diagnostics.md#rb-missing-operator"));
}

TEST_CASE("lsp: the warnings about a program's flow, as rb check gives them", "[lsp]") {
  Session s;
  s.initialize();
  json d = s.open(kUri, "rForward 10\nx = 0\nwhile x < 3\n  print x\nwend\n");
  REQUIRE(d.size() == 2);
  CHECK(d[0]["code"] == "rb-robot-not-placed");
  CHECK(d[0]["severity"] == 2);
  CHECK(d[1]["code"] == "rb-endless-loop");
  CHECK(d[1]["range"]["start"] == json{{"line", 2}, {"character", 6}});
  // None while the program has an error: one mistake, one message.
  std::vector<json> out = s.notify("textDocument/didChange",
      {{"textDocument", {{"uri", kUri}, {"version", 2}}},
       {"contentChanges", {{{"text", "rForward 10\nx = 0\nwhile x < 3\n  prnt x\nwend\n"}}}}});
  REQUIRE(out.size() == 1);
  json e = out[0]["params"]["diagnostics"];
  REQUIRE(e.size() == 1);
  CHECK(e[0]["severity"] == 1);
}

TEST_CASE("lsp: columns are counted in UTF-16 code units", "[lsp]") {
  Session s;
  s.initialize();
  // "é" is 2 bytes, 1 UTF-16 unit; "𝄞" is 4 bytes, 2 units.
  json d = s.open(kUri, "print \"é𝄞\" + rForwrd(1)\n");
  REQUIRE(d.size() >= 1);
  CHECK(d[0]["range"]["start"]["character"] == 14);
}

TEST_CASE("lsp: errors in an included file show on the #include line", "[lsp]") {
  Session s;
  s.disk.files["/work/p/lib.bas"] = "goto libEnd\nsub Helper(a)\n  prnt a\nendsub\nlibEnd:\n";
  s.initialize();
  json d = s.open(kUri, "x = 1\n#include \"lib.bas\"\nHelper(x)\n");
  REQUIRE(d.size() == 1);
  CHECK(d[0]["range"]["start"]["line"] == 1);
  CHECK(d[0]["message"].get<std::string>().find("in included file 'lib.bas', line 3") == 0);
  CHECK(d[0]["relatedInformation"][0]["location"]["uri"] == "file:///work/p/lib.bas");
  CHECK(d[0]["relatedInformation"][0]["location"]["range"]["start"]["line"] == 2);

  // Opening the library with the mistake fixed checks the program again with the editor's text.
  std::vector<json> out = s.notify("textDocument/didOpen",
      {{"textDocument", {{"uri", "file:///work/p/lib.bas"}, {"version", 1},
                         {"text", "goto libEnd\nsub Helper(a)\n  print a\nendsub\nlibEnd:\n"}}}});
  bool mainRechecked = false;
  for (const json& m : out)
    if (m["params"]["uri"] == kUri) {
      mainRechecked = true;
      CHECK(m["params"]["diagnostics"].empty());
    }
  CHECK(mainRechecked);

  // A missing include is an error on its line.
  d = s.open("file:///work/p/other.bas", "#include \"nothere.bas\"\n");
  REQUIRE(d.size() == 1);
  CHECK(d[0]["range"]["start"]["line"] == 0);
  CHECK(d[0]["message"].get<std::string>().find("not found") != std::string::npos);
}

TEST_CASE("lsp: hover shows a built-in's usage and description, any case", "[lsp]") {
  Session s;
  s.initialize();
  s.open(kUri, "RFORWARD 10\nx = atan2(1, 2)\nsub Move(a, &b)\n  b = a\nendsub\ncall Move(1, x)\n");
  json h = s.at("textDocument/hover", kUri, 0, 3);
  std::string text = h["result"]["contents"]["value"];
  CHECK(text.find("rForward") != std::string::npos);
  CHECK(text.find(std::string(rb::standardBuiltins().find("rForward", rb::BuiltinKind::Command)->help)) != std::string::npos);
  CHECK(h["result"]["range"]["end"]["character"] == 8);
  text = s.at("textDocument/hover", kUri, 1, 6)["result"]["contents"]["value"];
  CHECK(text.find("atan2(y, x)") != std::string::npos);
  text = s.at("textDocument/hover", kUri, 5, 7)["result"]["contents"]["value"];
  CHECK(text.find("sub Move(a, &b)") != std::string::npos);
  CHECK(s.at("textDocument/hover", kUri, 1, 0)["result"].is_null() == false);  // "x": a variable
  CHECK(s.at("textDocument/hover", kUri, 1, 11)["result"].is_null());          // a number
  CHECK(s.at("textDocument/hover", kUri, 99, 0)["result"].is_null());          // past the end
  text = s.at("textDocument/hover", kUri, 5, 1)["result"]["contents"]["value"];  // "call"
  CHECK(text.find("call Name(args)") != std::string::npos);
  CHECK(text.find("*keyword*") != std::string::npos);
}

TEST_CASE("lsp: every keyword has hover help", "[lsp]") {
  Session s;
  s.initialize();
  std::string text;
  for (std::string_view kw : rb::keywordSpellings()) text += std::string(kw) + "\n";
  s.open(kUri, text);
  int line = 0;
  for (std::string_view kw : rb::keywordSpellings()) {
    INFO(kw);
    json h = s.at("textDocument/hover", kUri, line++, 0)["result"];
    REQUIRE(h.is_object());
    CHECK(h["contents"]["value"].get<std::string>().find("*keyword*") != std::string::npos);
  }
}

TEST_CASE("lsp: completion offers what fits where the cursor is", "[lsp]") {
  Session s;
  s.initialize();
  s.open(kUri,
         "Real = 1\nreal = 2\nTop:\n  rFo\n  y = sq\n  goto \n  call \nsub Draw(n)\nendsub\nprint \"rF\n");
  json items = s.at("textDocument/completion", kUri, 3, 5)["result"];
  CHECK(hasLabel(items, "rForward"));   // a command at the start of a statement
  CHECK(hasLabel(items, "Real"));       // both spellings: names are case-sensitive
  CHECK(hasLabel(items, "real"));
  CHECK(hasLabel(items, "Draw"));
  CHECK(hasLabel(items, "while"));
  CHECK_FALSE(hasLabel(items, "sqrt"));  // a function cannot start a statement
  CHECK_FALSE(hasLabel(items, "rFo"));   // the word being typed is no variable

  items = s.at("textDocument/completion", kUri, 4, 8)["result"];
  CHECK(hasLabel(items, "sqrt"));
  CHECK(hasLabel(items, "Red"));
  CHECK(hasLabel(items, "Real"));
  CHECK_FALSE(hasLabel(items, "rForward"));

  items = s.at("textDocument/completion", kUri, 5, 7)["result"];
  CHECK(hasLabel(items, "Top"));
  CHECK(items.size() == 1);

  items = s.at("textDocument/completion", kUri, 6, 7)["result"];
  CHECK(hasLabel(items, "Draw"));
  CHECK(items.size() == 1);

  CHECK(s.at("textDocument/completion", kUri, 9, 9)["result"].empty());  // inside a string
  s.open("file:///work/p/r.bas", "x = 1 REM rFo\n");
  CHECK(s.at("textDocument/completion", "file:///work/p/r.bas", 0, 13)["result"].empty());  // a rem comment
}

TEST_CASE("lsp: completion offers the variables of the cursor's scope, and arrays", "[lsp]") {
  Session s;
  s.initialize();
  s.open(kUri, "total = 1\ndim grid[3]\n\nsub Move(size)\n  here = size\n  \nendsub\n");
  json items = s.at("textDocument/completion", kUri, 2, 0)["result"];
  CHECK(hasLabel(items, "total"));
  CHECK(hasLabel(items, "grid"));
  CHECK_FALSE(hasLabel(items, "here"));
  CHECK_FALSE(hasLabel(items, "size"));
  items = s.at("textDocument/completion", kUri, 5, 2)["result"];
  CHECK(hasLabel(items, "here"));
  CHECK(hasLabel(items, "size"));
  CHECK(hasLabel(items, "grid"));
  CHECK_FALSE(hasLabel(items, "total"));  // a sub's variables are its own
}

TEST_CASE("lsp: signature help for built-ins and subs", "[lsp]") {
  Session s;
  s.initialize();
  s.open(kUri, "x = atan2(1, \nrLocate 10, \nsub Move(a, &b)\nendsub\nMove(1, \n");
  json r = s.at("textDocument/signatureHelp", kUri, 0, 13)["result"];
  CHECK(r["signatures"][0]["label"] == "atan2(y, x)");
  CHECK(r["activeParameter"] == 1);
  CHECK(r["signatures"][0]["parameters"][1]["label"] == json{9, 10});
  r = s.at("textDocument/signatureHelp", kUri, 1, 12)["result"];
  CHECK(r["signatures"][0]["label"].get<std::string>().rfind("rLocate ", 0) == 0);
  CHECK(r["activeParameter"] == 1);
  r = s.at("textDocument/signatureHelp", kUri, 4, 8)["result"];
  CHECK(r["signatures"][0]["label"] == "Move(a, &b)");
  CHECK(r["activeParameter"] == 1);
}

TEST_CASE("lsp: go to definition of labels and subs, across #include", "[lsp]") {
  Session s;
  s.disk.files["/work/p/lib/shapes.bas"] = "goto shapesEnd\nsub Square(n)\nendsub\nshapesEnd:\n";
  s.initialize();
  s.open(kUri, "#include \"lib/shapes.bas\"\ngosub Draw\nSquare(3)\nend\nDraw:\nreturn\n");
  json r = s.at("textDocument/definition", kUri, 1, 8)["result"];
  REQUIRE(r.size() == 1);
  CHECK(r[0]["uri"] == kUri);
  CHECK(r[0]["range"]["start"] == json{{"line", 4}, {"character", 0}});
  r = s.at("textDocument/definition", kUri, 2, 2)["result"];
  REQUIRE(r.size() == 1);
  CHECK(r[0]["uri"] == "file:///work/p/lib/shapes.bas");
  CHECK(r[0]["range"]["start"] == json{{"line", 1}, {"character", 4}});
  CHECK(s.at("textDocument/definition", kUri, 1, 1)["result"].is_null());  // "gosub"
  // Labels are case-sensitive.
  s.open("file:///work/p/b.bas", "gosub draw\nend\nDraw:\nreturn\n");
  CHECK(s.at("textDocument/definition", "file:///work/p/b.bas", 0, 7)["result"].is_null());
}

TEST_CASE("lsp: document symbols list subs and labels", "[lsp]") {
  const std::string text = "Start:\ngosub Go\nend\nGo:\nreturn\nsub Move(a)\n  Inner:\n  a = 1\nendsub\n";
  SECTION("hierarchical") {
    Session s;
    s.initialize({{"textDocument", {{"documentSymbol", {{"hierarchicalDocumentSymbolSupport", true}}}}}});
    s.open(kUri, text);
    json r = s.request("textDocument/documentSymbol", {{"textDocument", {{"uri", kUri}}}})["result"];
    REQUIRE(r.size() == 3);
    CHECK(r[0]["name"] == "Move");
    CHECK(r[0]["kind"] == 12);
    CHECK(r[0]["range"]["start"]["line"] == 5);
    CHECK(r[0]["range"]["end"]["line"] == 8);
    REQUIRE(r[0]["children"].size() == 1);
    CHECK(r[0]["children"][0]["name"] == "Inner");
    CHECK(r[1]["name"] == "Start");
    CHECK(r[2]["name"] == "Go");
  }
  SECTION("flat") {
    Session s;
    s.initialize();
    s.open(kUri, text);
    json r = s.request("textDocument/documentSymbol", {{"textDocument", {{"uri", kUri}}}})["result"];
    REQUIRE(r.size() == 4);
    CHECK(r[3]["name"] == "Inner");
    CHECK(r[3]["containerName"] == "Move");
    CHECK(r[3]["location"]["uri"] == kUri);
  }
}

TEST_CASE("lsp: a run code lens for files", "[lsp]") {
  Session s;
  s.initialize();
  s.open(kUri, "print 1\n");
  json r = s.request("textDocument/codeLens", {{"textDocument", {{"uri", kUri}}}})["result"];
  REQUIRE(r.size() == 1);
  CHECK(r[0]["command"]["command"] == "rb.runFile");
  CHECK(r[0]["command"]["arguments"][0] == kUri);
}

TEST_CASE("lsp: shutdown, then exit", "[lsp]") {
  Session s;
  s.initialize();
  CHECK(s.request("shutdown")["result"].is_null());
  CHECK(s.at("textDocument/hover", kUri, 0, 0)["error"]["code"] == -32600);
  CHECK_FALSE(s.server.exitReceived());
  CHECK(s.sendRaw(R"({"jsonrpc":"2.0","method":"exit"})").empty());
  CHECK(s.server.exitReceived());
  CHECK(s.server.exitCode() == 0);

  Session t;
  t.initialize();
  t.sendRaw(R"({"jsonrpc":"2.0","method":"exit"})");
  CHECK(t.server.exitCode() == 1);  // exit without shutdown
}

namespace {
std::string frame(const json& j) {
  std::string body = j.dump();
  return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}
}  // namespace

TEST_CASE("lsp: run serves a whole session from a stream", "[lsp]") {
  std::string input =
      frame({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}, {"params", {{"capabilities", json::object()}}}}) +
      "Content-Length: 5\r\n\r\n{bad}" + "Garbage: yes\r\n\r\n" +
      frame({{"jsonrpc", "2.0"}, {"id", 2}, {"method", "shutdown"}}) +
      frame({{"jsonrpc", "2.0"}, {"method", "exit"}}) +
      frame({{"jsonrpc", "2.0"}, {"id", 3}, {"method", "shutdown"}});  // after exit: not read
  std::istringstream in(input);
  std::ostringstream out;
  MemoryDisk disk;
  rb::lsp::Server server(out, disk, rb::standardBuiltins(), {});
  CHECK(server.run(in) == 0);
  std::vector<json> replies = parseAll(out.str());
  REQUIRE(replies.size() == 4);
  CHECK(replies[0]["id"] == 1);
  CHECK(replies[1]["error"]["code"] == -32700);
  CHECK(replies[2]["error"]["code"] == -32700);
  CHECK(replies[3]["id"] == 2);
}

TEST_CASE("lsp: mutated sessions never crash or hang the server (fuzz-ish)", "[lsp]") {
  std::string valid =
      frame({{"jsonrpc", "2.0"}, {"id", 1}, {"method", "initialize"}, {"params", {{"capabilities", json::object()}}}}) +
      frame({{"jsonrpc", "2.0"}, {"method", "textDocument/didOpen"},
             {"params", {{"textDocument", {{"uri", kUri}, {"version", 1}, {"text", "sub A(x)\nrForward(x\nTop:\ngoto Top\n"}}}}}}) +
      frame({{"jsonrpc", "2.0"}, {"id", 2}, {"method", "textDocument/hover"},
             {"params", {{"textDocument", {{"uri", kUri}}}, {"position", {{"line", 1}, {"character", 3}}}}}}) +
      frame({{"jsonrpc", "2.0"}, {"id", 3}, {"method", "textDocument/completion"},
             {"params", {{"textDocument", {{"uri", kUri}}}, {"position", {{"line", 1}, {"character", 10}}}}}}) +
      frame({{"jsonrpc", "2.0"}, {"id", 4}, {"method", "textDocument/signatureHelp"},
             {"params", {{"textDocument", {{"uri", kUri}}}, {"position", {{"line", 1}, {"character", 10}}}}}}) +
      frame({{"jsonrpc", "2.0"}, {"id", 5}, {"method", "textDocument/definition"},
             {"params", {{"textDocument", {{"uri", kUri}}}, {"position", {{"line", 3}, {"character", 6}}}}}});
  std::mt19937 rng(7);
  for (int round = 0; round < 300; ++round) {
    std::string s = valid;
    for (int e = 0, n = 1 + static_cast<int>(rng() % 6); e < n; ++e) {
      size_t at = rng() % s.size();
      if (rng() % 2) s[at] = "{}[]\":,0123456789-ae\\ \n"[rng() % 23];
      else s.erase(at, 1 + rng() % 3);
    }
    std::istringstream in(s);
    std::ostringstream out;
    MemoryDisk disk;
    rb::lsp::Server server(out, disk, rb::standardBuiltins(), {});
    int code = server.run(in);
    CHECK((code == 0 || code == 1));
  }
}

TEST_CASE("lsp: rb.portable adds rb check --portable's warnings, from initializationOptions or settings", "[lsp]") {
  const std::string program = "x = sqrt(4) + kc_Enter\nprint x\n";
  auto portable = [](const json& diags) {
    int n = 0;
    for (const json& d : diags)
      if (d.value("code", "") == "rb-not-portable") {
        CHECK(d["message"].get<std::string>().find("'kc_Enter' is rb's own") == 0);
        ++n;
      }
    return n;
  };
  {
    Session s;
    s.initialize();
    CHECK(portable(s.open(kUri, program)) == 0);  // off unless asked for
    // Turned on by the settings (as VS Code sends its "rb" section): the open document again.
    json again;
    for (json& m : s.notify("workspace/didChangeConfiguration", {{"settings", {{"rb", {{"portable", true}}}}}}))
      if (m["method"] == "textDocument/publishDiagnostics") again = m["params"]["diagnostics"];
    CHECK(portable(again) == 1);
    // Settings that say nothing about it change nothing, and publish nothing.
    CHECK(s.notify("workspace/didChangeConfiguration", {{"settings", nullptr}}).empty());
  }
  {
    Session s;
    s.request("initialize", {{"capabilities", json::object()}, {"initializationOptions", {{"portable", true}}}});
    s.notify("initialized", json::object());
    json diags = s.open(kUri, "y = rtod(1) + kc_Enter\nprint y\n");
    REQUIRE(diags.size() == 1);
    CHECK(diags[0]["code"] == "rb-not-portable");
    CHECK(diags[0]["message"] == "'kc_Enter' is rb's own: no public RobotBASIC source names it\n"
                                 "note: what RobotBASIC is known to have instead: 13 (getKey gives character codes)");
  }
}
