#pragma once
// `rb lsp`: a Language Server Protocol server for RobotBASIC. It reads framed JSON-RPC
// messages from an input stream and writes its replies and notifications to an output stream,
// so tests drive it in-process with string streams. Documents are checked by the same loader,
// compiler and lint `rb check` uses; hover, signature help and completion come from the built-in
// table. See docs/editors.md.

#include <istream>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "lang/loader.h"
#include "text.h"

namespace rb {
class BuiltinTable;
}

namespace rb::lsp {

struct Analysis;

struct ServerOptions {
  LoadOptions load;                  ///< library folders for #include
  std::string version = "0.0.0";     ///< reported in serverInfo
  size_t maxMessageBytes = 0;        ///< 0: transport's default cap
};

class Server {
 public:
  /// `disk` reads files that are not open in the editor; `builtins` must outlive the server.
  Server(std::ostream& out, SourceReader& disk, const BuiltinTable& builtins, ServerOptions options);
  ~Server();

  /// Serves messages from `in` until `exit` or the end of the input. Returns the process's exit
  /// code: 0 after shutdown then exit, 1 otherwise (exit without shutdown, as LSP asks, and an
  /// input that ends without exit).
  int run(std::istream& in);

  /// Handles one message body (a JSON text). Replies go to the output stream.
  void handle(const std::string& body);

  bool exitReceived() const { return exited_; }
  /// 0 once `exit` came after `shutdown`, else 1.
  int exitCode() const { return exited_ && shutdown_ ? 0 : 1; }

 private:
  struct Document {
    std::string uri;
    std::string path;
    std::string text;
    int64_t version = 0;
    std::unique_ptr<Analysis> analysis;
  };
  class Reader;

  void dispatch(const nlohmann::json& msg);
  void reply(const nlohmann::json& id, nlohmann::json result);
  void replyError(const nlohmann::json& id, int code, const std::string& message);
  void notify(const std::string& method, nlohmann::json params);

  nlohmann::json initialize(const nlohmann::json& params);
  /// Takes the settings rb knows from initializationOptions or workspace/didChangeConfiguration
  /// (`rb.portable`: also rb check --portable's warnings); true when they changed.
  bool configure(const nlohmann::json& settings);
  void didOpen(const nlohmann::json& params);
  void didChange(const nlohmann::json& params);
  void didClose(const nlohmann::json& params);
  void fileChanged(const std::string& path);
  nlohmann::json hover(const nlohmann::json& params);
  /// What the rules of the diagnostics at (line, byteCol) of the open document mean (1-based; "" when none).
  std::string ruleHelpAt(const Analysis& a, uint32_t line, size_t byteCol) const;
  nlohmann::json completion(const nlohmann::json& params);
  nlohmann::json signatureHelp(const nlohmann::json& params);
  nlohmann::json definition(const nlohmann::json& params);
  nlohmann::json documentSymbol(const nlohmann::json& params);
  nlohmann::json codeLens(const nlohmann::json& params);

  /// Checks a document again and publishes its diagnostics.
  void check(Document& doc);
  void publish(const Document& doc);
  Document* document(const nlohmann::json& params);
  nlohmann::json range(const Analysis& a, SourceLoc loc) const;
  nlohmann::json location(const Analysis& a, SourceLoc loc) const;

  std::ostream& out_;
  SourceReader& disk_;
  const BuiltinTable& builtins_;
  ServerOptions options_;
  std::unique_ptr<Reader> reader_;
  std::map<std::string, Document> docs_;  ///< by URI
  Encoding encoding_ = Encoding::Utf16;
  bool hierarchicalSymbols_ = false;
  bool portable_ = false;  ///< rb.portable: documents are also checked as rb check --portable does
  bool initialized_ = false;
  bool shutdown_ = false;
  bool exited_ = false;
};

}  // namespace rb::lsp
