#include "transport.h"

#include <cctype>
#include <charconv>

namespace rb::lsp {

namespace {

constexpr size_t kMaxHeaderLine = 8192;
constexpr int kMaxHeaderLines = 64;

std::string lowerAscii(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

}  // namespace

bool MessageReader::readLine(std::string& line, bool& tooLong) {
  line.clear();
  tooLong = false;
  int c;
  while ((c = in_.get()) != std::char_traits<char>::eof()) {
    if (c == '\n') {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      return true;
    }
    if (line.size() < kMaxHeaderLine) line.push_back(static_cast<char>(c));
    else tooLong = true;
  }
  return false;  // the input ended before the line did
}

bool MessageReader::skipBody() {
  char buf[1 << 14];
  while (skip_ > 0) {
    in_.read(buf, static_cast<std::streamsize>(skip_ < sizeof buf ? skip_ : sizeof buf));
    if (in_.gcount() == 0) return false;
    skip_ -= static_cast<unsigned long long>(in_.gcount());
  }
  return true;
}

bool MessageReader::findHeader() {
  std::string line;
  bool tooLong = false;
  while (readLine(line, tooLong)) {
    // A header starts where a body it did not know the length of ended: anywhere in the line.
    size_t at = lowerAscii(line).find("content-length:");
    if (!tooLong && at != std::string::npos) {
      firstLine_ = line.substr(at);
      return true;
    }
    line.clear();
    tooLong = false;
  }
  return false;
}

MessageReader::Result MessageReader::next() {
  Result r;
  if ((skip_ > 0 && !skipBody()) || (resync_ && !findHeader())) {
    skip_ = 0;
    r.status = Status::End;
    return r;
  }
  resync_ = false;
  for (;;) {
    // One header block: lines up to an empty one. Empty lines before a block are skipped.
    std::string line;
    bool tooLong = false;
    bool haveLength = false;
    bool badLength = false;
    unsigned long long length = 0;
    int lines = 0;
    bool started = false;
    for (;;) {
      if (!firstLine_.empty()) {
        line = std::move(firstLine_);
        firstLine_.clear();
      } else if (!readLine(line, tooLong)) {
        r.status = Status::End;
        return r;
      }
      if (line.empty() && !tooLong) {
        if (started) break;
        continue;
      }
      started = true;
      if (++lines > kMaxHeaderLines || tooLong) {
        badLength = true;
        continue;
      }
      size_t colon = line.find(':');
      if (colon == std::string::npos) {
        badLength = true;
        continue;
      }
      std::string name = lowerAscii(trim(line.substr(0, colon)));
      std::string value = trim(line.substr(colon + 1));
      if (name == "content-length") {
        auto [p, ec] = std::from_chars(value.data(), value.data() + value.size(), length);
        if (ec != std::errc() || p != value.data() + value.size() || value.empty() || haveLength)
          badLength = true;
        haveLength = true;
      }
    }
    if (!haveLength || badLength) {
      r.status = Status::BadHeader;
      resync_ = true;  // whatever follows belongs to no message: find the next header
      r.why = !haveLength ? "a message header without Content-Length"
                          : "a malformed message header";
      return r;
    }
    if (length > maxBytes_) {
      // Said at once; the body is read away by the next call, so the next message is found. A
      // length past kMaxSkippedBytes is not believed: the next header line is looked for.
      if (length <= kMaxSkippedBytes) skip_ = length;
      else resync_ = true;
      r.status = Status::TooLarge;
      r.why = "a message of " + std::to_string(length) + " bytes (the limit is " +
              std::to_string(maxBytes_) + ")";
      return r;
    }
    r.body.resize(static_cast<size_t>(length));
    in_.read(r.body.data(), static_cast<std::streamsize>(length));
    if (static_cast<unsigned long long>(in_.gcount()) != length) {
      r.body.clear();
      r.status = Status::End;
      return r;
    }
    r.status = Status::Ok;
    return r;
  }
}

void writeMessage(std::ostream& out, const std::string& body) {
  out << "Content-Length: " << body.size() << "\r\n\r\n" << body;
  out.flush();
}

}  // namespace rb::lsp
