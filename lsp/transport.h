#pragma once
// The Language Server Protocol's transport: messages framed by a `Content-Length: N` header
// block (ended by an empty line) and a body of N bytes of JSON-RPC 2.0. Reading never trusts its
// input: header lines, header blocks and bodies are capped, and a malformed block is skipped
// with a status that says why, so the server can answer and read on.

#include <cstddef>
#include <istream>
#include <ostream>
#include <string>

namespace rb::lsp {

/// The largest message body accepted (a whole document in a didOpen is far smaller).
constexpr size_t kMaxMessageBytes = 32u << 20;
/// The largest Content-Length believed: a body above the cap but within this is read and dropped
/// (so the next message is found); beyond it the header is a lie, and the reader looks for the
/// next `Content-Length:` line instead of waiting for exabytes.
constexpr unsigned long long kMaxSkippedBytes = 1ull << 30;

class MessageReader {
 public:
  enum class Status {
    Ok,         ///< `body` holds one message
    End,        ///< the input ended (cleanly or in the middle of a message)
    BadHeader,  ///< a header block without a usable Content-Length (it was skipped)
    /// Content-Length above the cap: said at once; the body is read and dropped by the next
    /// call (or, past kMaxSkippedBytes, the next header line is looked for)
    TooLarge,
  };
  struct Result {
    Status status = Status::End;
    std::string body;
    std::string why;  ///< for BadHeader and TooLarge: what was wrong, for the error reply
  };

  explicit MessageReader(std::istream& in, size_t maxBytes = kMaxMessageBytes)
      : in_(in), maxBytes_(maxBytes) {}

  /// Reads the next message.
  Result next();

 private:
  /// One header line without its line end; false at the end of input.
  bool readLine(std::string& line, bool& tooLong);

  /// Reads away a dropped body; false when the input ended first.
  bool skipBody();
  /// Reads lines up to the next one that holds `Content-Length:`; false at the end.
  bool findHeader();

  std::istream& in_;
  size_t maxBytes_;
  unsigned long long skip_ = 0;  ///< bytes of a dropped body still to read away
  bool resync_ = false;          ///< a header lied: look for the next Content-Length line
  std::string firstLine_;        ///< the header line findHeader() found, read first
};

/// Writes one message with its header and flushes.
void writeMessage(std::ostream& out, const std::string& body);

}  // namespace rb::lsp
