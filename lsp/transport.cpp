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

MessageReader::Result MessageReader::next() {
  Result r;
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
      if (!readLine(line, tooLong)) {
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
      r.why = !haveLength ? "a message header without Content-Length"
                          : "a malformed message header";
      return r;
    }
    if (length > maxBytes_) {
      // Read the body away without keeping it, so the next message is found.
      char buf[1 << 14];
      unsigned long long left = length;
      while (left > 0 && in_) {
        in_.read(buf, static_cast<std::streamsize>(left < sizeof buf ? left : sizeof buf));
        left -= static_cast<unsigned long long>(in_.gcount());
        if (in_.gcount() == 0) break;
      }
      if (left > 0) {
        r.status = Status::End;
        return r;
      }
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
