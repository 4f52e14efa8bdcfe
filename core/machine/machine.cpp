#include "machine/machine.h"

#include "base/runtime_error.h"

namespace rb {

void Machine::print(std::string_view text, bool newline) {
  ++prints_;
  std::string line(text);
  canvas_.print(line, newline);
  if (newline) line += '\n';
  host_.output(line);
  // Printing is slow work (text drawn on the screen, output written): the limits are looked at
  // after every print, not only every 65,536 statements.
  checkAlarms();
}

std::string Machine::input(std::string_view prompt) {
  ++prints_;  // the prompt and the typed line are printed too
  if (!prompt.empty()) canvas_.print(std::string(prompt), false);
  std::optional<std::string> line = host_.inputLine(prompt);
  if (!line) throw RuntimeError("input: no more input to read (end of input)");
  canvas_.print(*line, true);
  return *line;
}

void Machine::delay(double ms) {
  if (ms > 0) host_.wait(ms);
}

void Machine::robotStepped() {
  double ms = robotSpeed + host_.robotStepMs();
  if (ms > 0) host_.wait(ms);
  host_.animate();
}

bool Machine::animatesRobot() const { return robotSpeed > 0 || host_.robotStepMs() > 0; }

void Machine::printPrompt(std::string_view prompt) {
  if (prompt.empty() || (prompt == lastPrompt_ && prints_ == promptPrintedAt_)) return;
  print(prompt, false);
  lastPrompt_ = prompt;
  promptPrintedAt_ = prints_;
}

void Machine::raiseAlarm() const {
  if (alarms_.now() & RunAlarms::kMemory) {
    throw RuntimeError("out of memory: rb uses more than " + std::to_string(memoryLimit >> 20) +
                       " MiB (the --max-memory limit)");
  }
  throw DeadlinePassed{};
}

namespace {
/// Past this many bytes, what the run holds is asked of the host (it reads the process's memory).
constexpr uint64_t kAskHostFrom = uint64_t{1} << 16;
}  // namespace

bool Machine::memoryFits(uint64_t bytes) {
  if (!memoryLimit) return true;
  uint64_t held = bytes > kAskHostFrom ? host_.memoryInUse() : 0;
  return bytes <= memoryLimit && held + bytes <= memoryLimit;
}

void Machine::reserveMemory(uint64_t bytes, std::string_view what) {
  if (!memoryLimit) return;
  uint64_t held = bytes > kAskHostFrom ? host_.memoryInUse() : 0;
  if (bytes <= memoryLimit && held + bytes <= memoryLimit) return;
  std::string msg = "out of memory: " + std::string(what) + " would need " + std::to_string(bytes >> 20) + " MiB";
  if (bytes <= memoryLimit) msg += " beside the " + std::to_string(held >> 20) + " MiB the run holds already";
  throw RuntimeError(msg + ", more than the " + std::to_string(memoryLimit >> 20) + " MiB of the --max-memory limit");
}

void Machine::useCommPort(int64_t port) {
  real_.reset();  // closes the previous port, if any
  if (port != 0) connectRobot(host_.openRobot(port));
}

void Machine::connectRobot(std::unique_ptr<RobotLink> link) {
  real_.reset();
  link->setWhileWaiting([this] { checkAlarms(); });
  real_ = std::make_unique<RealRobot>(std::move(link));
  real_->betweenCommands = [this] { checkAlarms(); };
}

void Machine::emit(RobotEvent::Kind kind, std::string_view command, std::string args,
                   std::optional<double> value) {
  if (!observer_) return;
  RobotEvent e{kind, command, location_, std::move(args), robot().pose(), robot().penDown(), value};
  observer_->robotEvent(e);
}

}  // namespace rb
