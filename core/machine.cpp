#include "machine.h"

#include "runtime_error.h"

namespace rb {

void Machine::print(std::string_view text, bool newline) {
  if (newline) {
    std::string line(text);
    line += '\n';
    host_.output(line);
  } else {
    host_.output(text);
  }
}

std::string Machine::input(std::string_view prompt) {
  std::optional<std::string> line = host_.inputLine(prompt);
  if (!line) throw RuntimeError("input: no more input to read (end of input)");
  return *line;
}

void Machine::delay(double ms) {
  if (ms > 0) host_.wait(ms);
}

}  // namespace rb
