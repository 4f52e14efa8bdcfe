#include "web_host.h"

#include <emscripten.h>
#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "robot_image.h"
#include "robot_view.h"
#include "json_text.h"
#include "svg_writer.h"
#include "base/number.h"
#include "base/runtime_error.h"
#include "robot/protocol.h"
#include "robot/reply_check.h"

// The page's side of each call: Module.rbHooks, set by web/rb.js for each run. The async ones
// suspend the run (Asyncify) until the page answers; the page answers at once after a Stop.
// clang-format off
EM_JS(void, rb_js_output, (const char* text, int size), { Module.rbHooks.output(UTF8ToString(text, size)); });
EM_JS(int, rb_js_stopped, (), { return Module.rbHooks.stopped() ? 1 : 0; });
EM_JS(double, rb_js_step_ms, (), { return Module.rbHooks.stepMs(); });
EM_JS(int, rb_js_stepping, (), { return Module.rbHooks.stepping() ? 1 : 0; });
#ifndef RB_NO_ASYNC
EM_ASYNC_JS(void, rb_js_at_line, (int line), { await Module.rbHooks.atLine(line); });
#endif
EM_JS(void, rb_js_state, (const char* json, int size), { Module.rbHooks.state(UTF8ToString(json, size)); });
EM_JS(void, rb_js_frame, (const uint8_t* rgba, int width, int height), { Module.rbHooks.frame(rgba, width, height); });
EM_JS(void, rb_js_svg, (const char* svg, int size, const uint8_t* rgba, int width, int height), {
  Module.rbHooks.svg(UTF8ToString(svg, size), rgba ? new Uint8ClampedArray(HEAPU8.subarray(rgba, rgba + width * height * 4)) : null,
                     width, height);
});
#ifndef RB_NO_ASYNC
EM_ASYNC_JS(void, rb_js_yield, (double ms), { await Module.rbHooks.yield(ms); });
#endif
#ifndef RB_NO_ASYNC
EM_ASYNC_JS(char*, rb_js_input_line, (const char* prompt), {
  const line = await Module.rbHooks.inputLine(UTF8ToString(prompt));
  if (line === null || line === undefined) return 0;
  const size = lengthBytesUTF8(line) + 1;
  const p = _malloc(size);
  stringToUTF8(line, p, size);
  return p;
});
#endif
#ifndef RB_NO_ASYNC
// Web Serial (web/app.js). Open: the page asks the user for a port and opens it; the answer is
// the port's name, or "!" and why not. Send: drops what waits unread, writes the command; 0 when
// the port has gone. Take: waits up to `ms` for `want` bytes in all, then gives what came (at
// most `room`); -1 when the port has gone.
EM_ASYNC_JS(char*, rb_js_serial_open, (int port), {
  const r = await Module.rbHooks.serialOpen(port);
  const text = r.error ? '!' + r.error : r.name;
  const size = lengthBytesUTF8(text) + 1;
  const p = _malloc(size);
  stringToUTF8(text, p, size);
  return p;
});
EM_ASYNC_JS(int, rb_js_serial_send, (int code, int param), { return (await Module.rbHooks.serialSend(code, param)) ? 1 : 0; });
EM_ASYNC_JS(int, rb_js_serial_take, (int want, double ms, uint8_t* out, int room), {
  const bytes = await Module.rbHooks.serialTake(want, ms, room);
  if (!bytes) return -1;
  HEAPU8.set(bytes, out);
  return bytes.length;
});
EM_JS(void, rb_js_serial_close, (), { Module.rbHooks.serialClose(); });
#endif
EM_JS(int, rb_js_held_key, (), { return Module.rbHooks.heldKey(); });
EM_JS(int, rb_js_take_typed, (), { return Module.rbHooks.takeTyped(); });
EM_JS(void, rb_js_controls, (const char* json, int size), { Module.rbHooks.controls(JSON.parse(UTF8ToString(json, size))); });
#ifndef RB_NO_ASYNC
EM_ASYNC_JS(int, rb_js_wait_key, (), { return await Module.rbHooks.waitKey(); });
#endif
EM_JS(void, rb_js_mouse, (int* out), {
  const m = Module.rbHooks.mouse();
  HEAP32[out >> 2] = m[0]; HEAP32[(out >> 2) + 1] = m[1]; HEAP32[(out >> 2) + 2] = m[2];
});
EM_JS(int, rb_js_take_click, (int* out), {
  const c = Module.rbHooks.takeClick();
  if (!c) return 0;
  HEAP32[out >> 2] = c[0]; HEAP32[(out >> 2) + 1] = c[1]; HEAP32[(out >> 2) + 2] = c[2];
  return 1;
});
#ifndef RB_NO_ASYNC
EM_ASYNC_JS(void, rb_js_wait_click, (int* out), {
  const c = await Module.rbHooks.waitClick();
  HEAP32[out >> 2] = c[0]; HEAP32[(out >> 2) + 1] = c[1]; HEAP32[(out >> 2) + 2] = c[2];
});
#endif
#ifndef RB_NO_ASYNC
EM_ASYNC_JS(void, rb_js_message_box, (const char* text, const char* title), {
  await Module.rbHooks.messageBox(UTF8ToString(text), UTF8ToString(title));
});
#endif
#ifdef RB_NO_ASYNC
// rb.run's module (rbcore_fast: a Web Worker or node, headless): nothing waits for the page.
// Headless runs never ask for input lines, keys, clicks or message boxes from the page (they
// come from the given lines and scripted input), nor step.
static void rb_js_yield(double) {}
static char* rb_js_input_line(const char*) { return nullptr; }
static int rb_js_wait_key() { return 0; }
static void rb_js_wait_click(int* out) { out[0] = out[1] = out[2] = 0; }
static void rb_js_message_box(const char*, const char*) {}
static void rb_js_at_line(int) {}
#endif
// clang-format on

namespace rb::web {

namespace {
/// Computing time between two yields to the page: short enough for smooth frames and a Stop
/// within a frame, long enough that yielding costs little.
constexpr double kLiveSliceMs = 12;
constexpr double kHeadlessSliceMs = 40;
/// Frames at most this often.
constexpr double kFrameMs = 16;
/// Waits shorter than this add up before the run sleeps (a timer's resolution).
constexpr double kShortestSleepMs = 10;
/// How far the virtual clock moves each time the program reads it (as HeadlessHost).
constexpr double kClockReadMs = 1.0;
/// The most of a printed line the state keeps (bytes).
constexpr size_t kPrintedCap = 200;

/// `s` cut to kPrintedCap bytes, not inside a UTF-8 character.
void capPrinted(std::string& s) {
  if (s.size() <= kPrintedCap) return;
  size_t n = kPrintedCap;
  while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;
  s.resize(n);
}

bool blank(std::string_view s) { return s.find_first_not_of(" \t\r") == std::string_view::npos; }

/// A number as rb prints it, to a tenth (the pose).
std::string tenths(double v) { return formatNumber(std::round(v * 10) / 10); }
}  // namespace

WebHost::WebHost(bool live, std::vector<std::string> stdinLines, InputScript script)
    : live_(live),
      stdin_(std::move(stdinLines)),
      script_(std::move(script), virtualMs_),
      start_(std::chrono::steady_clock::now()) {}

void WebHost::attachMachine(Machine& machine) {
  machine_ = &machine;
  if (live_) stepMs_ = rb_js_step_ms();
  if (live_) stepping_ = rb_js_stepping() != 0;
  setWantsLines(stepping_);
  script_.useControls(&machine.controls);
}

void WebHost::output(std::string_view text) {
  out_ += text;
  if (out_.size() >= (1u << 16)) flushOutput();
  // The last line printed that is not blank, and the one being printed.
  size_t at = 0;
  for (size_t end; (end = text.find('\n', at)) != std::string_view::npos; at = end + 1) {
    if (lineNow_.size() < kPrintedCap) lineNow_ += text.substr(at, std::min(end - at, kPrintedCap));
    capPrinted(lineNow_);
    if (!blank(lineNow_)) {
      if (!lineNow_.empty() && lineNow_.back() == '\r') lineNow_.pop_back();
      lastLine_ = std::move(lineNow_);
    }
    lineNow_.clear();
  }
  if (at < text.size() && lineNow_.size() < kPrintedCap) {
    lineNow_ += text.substr(at, std::min(text.size() - at, kPrintedCap));
    capPrinted(lineNow_);
  }
}

std::string WebHost::stateJson() const {
  std::string json = "{\"line\":" + std::to_string(machine_ ? machine_->location().line : 0);
  if (machine_) {
    const Robot& robot = machine_->robot();
    json += ",\"placed\":" + std::string(robot.located() ? "true" : "false");
    if (robot.located()) {
      const Pose& pose = robot.pose();
      json += ",\"x\":\"" + tenths(pose.pos.x()) + "\",\"y\":\"" + tenths(pose.pos.y()) + "\",\"heading\":\"" +
              tenths(pose.heading) + "\",\"pen\":" + (robot.penDown() ? "true" : "false");
    }
  }
  // Each sensor's last reading (the machine keeps them), the latest first.
  std::vector<SensorReading> readings;
  if (machine_) readings = machine_->lastReadings();
  std::sort(readings.begin(), readings.end(),
            [](const SensorReading& a, const SensorReading& b) { return a.order > b.order; });
  json += ",\"sensors\":[";
  for (size_t i = 0; i < readings.size(); ++i) {
    if (i) json += ',';
    json += "{\"name\":";
    render::appendJsonString(json, readings[i].name);
    json += ",\"value\":\"" + formatNumber(readings[i].value) + "\",\"line\":" +
            std::to_string(readings[i].loc.line) + "}";
  }
  json += "],\"printed\":";
  render::appendJsonString(json, blank(lineNow_) ? lastLine_ : lineNow_);
  return json + "}";
}

void WebHost::presentState(bool force) {
  if (!live_ || !machine_) return;
  const double now = wallSeconds() * 1000;
  if (!force && now - lastStateMs_ < kStateEveryMs) return;
  lastStateMs_ = now;
  std::string json = stateJson();
  if (json == stateJson_) return;
  stateJson_ = std::move(json);
  rb_js_state(stateJson_.data(), static_cast<int>(stateJson_.size()));
}

void WebHost::flushOutput() {
  if (out_.empty()) return;
  rb_js_output(out_.data(), static_cast<int>(out_.size()));
  out_.clear();
}

void WebHost::armWatchdog(const WatchdogLimits& limits, RunAlarms& alarms) {
  limits_ = limits;
  alarms_ = &alarms;
}

void WebHost::disarmWatchdog() { alarms_ = nullptr; }

void WebHost::checkLimits() {
  if (!alarms_) return;
  if (limits_.seconds > 0 && wallSeconds() >= limits_.seconds) alarms_->raise(RunAlarms::kDeadline);
  if (limits_.memoryBytes > 0 && memoryInUse() > limits_.memoryBytes) alarms_->raise(RunAlarms::kMemory);
}

double WebHost::wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double WebHost::clockMs() {
  if (live_) return wallSeconds() * 1000 + sleepDebtMs_;
  virtualMs_ += kClockReadMs;
  return virtualMs_;
}

void WebHost::yieldToPage(bool force) {
  double now = wallSeconds() * 1000;
  if (!force && now - lastYieldMs_ < (live_ ? kLiveSliceMs : kHeadlessSliceMs)) return;
  checkLimits();
  flushOutput();
  presentState(false);
  if (live_ && now - lastFrameMs_ >= kFrameMs) {
    present();
    lastFrameMs_ = now;
  }
  rb_js_yield(0);
  lastYieldMs_ = wallSeconds() * 1000;
  afterPage();
}

void WebHost::afterPage() {
  if (rb_js_stopped()) requestStop();
  if (!live_) return;
  stepMs_ = rb_js_step_ms();  // the page's speed may have changed
  stepping_ = rb_js_stepping() != 0;
  setWantsLines(stepping_);  // a statement costs a call into the host only while stepping
  // Keys typed while an edit box has the keyboard (the page sends them here, not to the
  // program, while the controls it was last shown say so): into the box, by core/input's rules.
  if (!machine_) return;
  bool typed = false;
  while (int key = rb_js_take_typed()) typed = rules_.typeInto(machine_->controls, key) || typed;
  if (typed) presentControls();
}

void WebHost::onLine(SourceLoc loc) {
  // Only live runs are compiled with this hook; it costs a test per statement until the page
  // asks for steps.
  if (!stepping_ || loc.file != 0 || stopRequested()) return;
  flushOutput();
  present();
  presentState(true);
  lastFrameMs_ = wallSeconds() * 1000;
  rb_js_at_line(static_cast<int>(loc.line));
  lastYieldMs_ = wallSeconds() * 1000;
  afterPage();
}

void WebHost::wait(double ms) {
  if (!(ms > 0)) return;
  if (!live_) {
    virtualMs_ += ms;
    yieldToPage(false);
    return;
  }
  sleepDebtMs_ += ms;
  if (sleepDebtMs_ < kShortestSleepMs) {
    yieldToPage(false);
    return;
  }
  flushOutput();
  present();
  presentState(false);
  // In pieces, so that a Stop during a long delay ends it within one piece.
  while (sleepDebtMs_ > 0 && !stopRequested()) {
    double piece = std::min(sleepDebtMs_, 50.0);
    double before = wallSeconds() * 1000;
    rb_js_yield(piece);
    sleepDebtMs_ -= wallSeconds() * 1000 - before;
    afterPage();
  }
  sleepDebtMs_ = 0;
  lastYieldMs_ = lastFrameMs_ = wallSeconds() * 1000;
}

bool WebHost::poll() {
  yieldToPage(false);
  return !stopRequested();
}

void WebHost::animate() { yieldToPage(false); }

// What malloc has handed out now: the wasm heap itself only grows, so its size would count a
// past run's memory against the next one.
uint64_t WebHost::memoryInUse() {
  struct mallinfo info = mallinfo();
  return static_cast<uint64_t>(static_cast<unsigned>(info.uordblks)) + static_cast<unsigned>(info.hblkhd);
}

std::optional<std::string> WebHost::inputLine(std::string_view prompt) {
  output(prompt);
  std::optional<std::string> line;
  if (!live_) {
    if (script_.given()) {
      line = script_.inputLine("input");
    } else if (nextLine_ < stdin_.size()) {
      line = stdin_[nextLine_++];
    }
    if (line) {
      output(*line);  // as from a pipe: the line read is written after the prompt
      output("\n");
    }
    return line;
  }
  flushOutput();
  present();
  presentState(true);
  std::string promptText(prompt);
  char* p = rb_js_input_line(promptText.c_str());
  if (rb_js_stopped()) requestStop();
  if (!p) return std::nullopt;
  line = std::string(p);
  std::free(p);
  output(*line);
  output("\n");
  return line;
}

int64_t WebHost::heldKey(std::string_view who) {
  if (!live_) return script_.heldKey(who);
  yieldToPage(false);
  return rb_js_held_key();
}

int64_t WebHost::waitKey(std::string_view who) {
  if (!live_) return script_.waitKey(who);
  flushOutput();
  present();
  presentState(true);
  int64_t key = rb_js_wait_key();
  if (rb_js_stopped()) requestStop();
  return key;
}

MouseState WebHost::mouse(std::string_view who) {
  if (!live_) return script_.mouse(who);
  yieldToPage(false);
  int m[3] = {0, 0, 0};
  rb_js_mouse(m);
  return {m[0], m[1], m[2]};
}

MouseState WebHost::waitClick(std::string_view who) {
  if (!live_) return script_.waitClick(who);
  flushOutput();
  present();
  presentState(true);
  int m[3] = {0, 0, 0};
  rb_js_wait_click(m);
  if (rb_js_stopped()) requestStop();
  return {m[0], m[1], m[2]};
}

void WebHost::updateControls(Controls& controls, std::string_view who) {
  if (!live_) {
    script_.updateControls(controls, who);
    return;
  }
  yieldToPage(false);
  int c[3];
  while (rb_js_take_click(c)) rules_.press(controls, c[0], c[1]);
  presentControls();
}

void WebHost::presentControls() {
  if (!machine_ || !live_) return;
  const Controls& controls = machine_->controls;
  std::string json = "{\"buttons\":[";
  auto box = [&json](std::string_view name, int x, int y, int w, int h) {
    json += "{\"name\":";
    render::appendJsonString(json, name);
    json += ",\"x\":" + std::to_string(x) + ",\"y\":" + std::to_string(y) + ",\"w\":" + std::to_string(w) +
            ",\"h\":" + std::to_string(h);
  };
  for (size_t i = 0; i < controls.buttons.size(); ++i) {
    const Button& b = controls.buttons[i];
    if (i) json += ',';
    box(b.name, b.x, b.y, b.width, b.height);
    json += '}';
  }
  json += "],\"edits\":[";
  for (size_t i = 0; i < controls.edits.size(); ++i) {
    const EditBox& e = controls.edits[i];
    if (i) json += ',';
    box(e.name, e.x, e.y, e.width, e.height);
    json += ",\"text\":";
    render::appendJsonString(json, e.text);
    json += '}';
  }
  json += "],\"focus\":";
  render::appendJsonString(json, rules_.focusedEdit());
  json += '}';
  if (json == controlsJson_) return;
  controlsJson_ = std::move(json);
  rb_js_controls(controlsJson_.data(), static_cast<int>(controlsJson_.size()));
}

void WebHost::messageBox(std::string_view text, std::string_view title) {
  if (!live_) {
    script_.messageBox("MsgBox");
    return;
  }
  flushOutput();
  present();
  presentState(true);
  std::string t(text), h(title);
  rb_js_message_box(t.c_str(), h.c_str());
  if (rb_js_stopped()) requestStop();
}

bool WebHost::toRgba(const Pixels& pixels) {
  constexpr size_t n = static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight;
  if (pixels.size() < n) return false;
  rgba_.resize(n * 4);
  uint8_t* o = rgba_.data();
  for (size_t i = 0; i < n; ++i, o += 4) {
    uint32_t rgb = colourToRgb(pixels[i]);
    o[0] = static_cast<uint8_t>(rgb >> 16), o[1] = static_cast<uint8_t>(rgb >> 8),
    o[2] = static_cast<uint8_t>(rgb), o[3] = 255;
  }
  return true;
}

void WebHost::present() {
  if (!machine_) return;
  presentControls();
  constexpr int w = Canvas::kWidth, h = Canvas::kHeight;
  // The same screen and robot as the frame before: nothing to send (a long computation draws
  // nothing, and converting the screen costs 2 ms).
  const render::RobotView view = render::robotView(*machine_);
  const Shown now{machine_->canvas().version(), machine_->flips, machine_->showsFlip(), view.visible,
                  view.x, view.y, view.heading, view.radius, view.colour};
  if (now == lastShown_) return;
  lastShown_ = now;
  if (!toRgba(machine_->shownScreen())) return;
  // The robot on top, as rb render's picture and the live terminal view draw it.
  const render::RobotImage shape(view);
  const uint32_t robotRgb = colourToRgb(view.colour);
  if (!shape.empty())
    shape.rasterize(1, w, h, [&](int x, int y) {
      uint8_t* p = rgba_.data() + (static_cast<size_t>(y) * w + static_cast<size_t>(x)) * 4;
      p[0] = static_cast<uint8_t>(robotRgb >> 16), p[1] = static_cast<uint8_t>(robotRgb >> 8),
      p[2] = static_cast<uint8_t>(robotRgb);
    });
  rb_js_frame(rgba_.data(), w, h);
}

void WebHost::presentSvg() {
  if (!machine_) return;
  // The embedded pixels' PNG, when the SVG embeds them, is made on the page (rb.js) with the
  // browser's deflate: here the SVG names them kScreenHref.
  bool havePixels = false;
  const std::string svg = render::renderSvg(
      machine_->canvas(), render::robotView(*machine_), 1, machine_->showsFlip() ? &machine_->shownScreen() : nullptr,
      [&](const Pixels& pixels) {
        havePixels = toRgba(pixels);
        return std::string(kScreenHref);
      });
  rb_js_svg(svg.data(), static_cast<int>(svg.size()), havePixels ? rgba_.data() : nullptr, Canvas::kWidth,
            Canvas::kHeight);
}

#ifndef RB_NO_ASYNC
/// A robot on a Web Serial port: one command at a time, two bytes out and five back within the
/// timeout, judged as the serial link judges them. It waits in pieces of at most 50 ms, so the
/// page's Stop and the run's limits end a wait for a robot that does not answer.
class WebSerialLink : public RobotLink {
 public:
  WebSerialLink(WebHost& host, std::string name, double timeoutSeconds)
      : host_(host), name_(std::move(name)), timeoutSeconds_(timeoutSeconds) {}
  ~WebSerialLink() override { rb_js_serial_close(); }

  RobotReply transact(uint8_t code, uint8_t param) override {
    if (broken_) throw RuntimeError("robot on " + name_ + " is disconnected after an earlier fault");
    if (host_.stopRequested()) return {};
    protocol::Exchange exchange;
    const double deadline = host_.wallSeconds() * 1000 + timeoutSeconds_ * 1000;
    if (!rb_js_serial_send(code, param)) exchange.end = protocol::Exchange::End::HungUp;
    uint8_t room[protocol::kMaxReadReply];
    while (exchange.end == protocol::Exchange::End::Complete) {
      const bool full = exchange.bytes.size() >= static_cast<size_t>(protocol::kReplySize);
      const double left = deadline - host_.wallSeconds() * 1000;
      // Once a reply's worth is in, what came with it at once (a longer reply is a fault).
      const int want = full ? 0 : protocol::kReplySize - static_cast<int>(exchange.bytes.size());
      const int got = rb_js_serial_take(want, full ? 0 : std::clamp(left, 0.0, 50.0), room,
                                        static_cast<int>(protocol::kMaxReadReply - exchange.bytes.size()));
      if (got < 0) {
        exchange.end = protocol::Exchange::End::HungUp;
        break;
      }
      exchange.bytes.insert(exchange.bytes.end(), room, room + got);
      if (full || exchange.bytes.size() >= protocol::kMaxReadReply) break;
      if (exchange.bytes.size() >= static_cast<size_t>(protocol::kReplySize)) continue;
      host_.afterPage();
      host_.checkLimits();
      if (whileWaiting_) whileWaiting_();  // the run's limits end the wait
      if (host_.stopRequested()) return {};
      if (host_.wallSeconds() * 1000 >= deadline) exchange.end = protocol::Exchange::End::TimedOut;
    }
    if (auto message = protocol::replyFault(exchange, name_, timeoutSeconds_)) {
      broken_ = true;  // after a fault the byte stream can no longer be trusted
      throw RuntimeError(*message);
    }
    return protocol::decodeExchange(exchange);
  }
  std::string name() const override { return name_; }
  void setWhileWaiting(std::function<void()> hook) override { whileWaiting_ = std::move(hook); }

 private:
  WebHost& host_;
  std::string name_;
  double timeoutSeconds_;
  bool broken_ = false;
  std::function<void()> whileWaiting_;
};
#endif

std::unique_ptr<RobotLink> WebHost::openRobot(int64_t port) {
#ifdef RB_NO_ASYNC
  (void)port;
  throw RuntimeError("rCommPort " + std::to_string(port) +
                     ": rb.run drives no real robot; run the program on the page to use a robot over Web Serial");
#else
  if (!live_) return Host::openRobot(port);
  flushOutput();
  present();
  char* answer = rb_js_serial_open(static_cast<int>(port));
  std::string text = answer ? answer : "!the page did not answer";
  std::free(answer);
  if (stopRequested()) throw RuntimeError("rCommPort " + std::to_string(port) + ": the run was stopped");
  if (!text.empty() && text[0] == '!') throw RuntimeError("rCommPort " + std::to_string(port) + ": " + text.substr(1));
  return std::make_unique<WebSerialLink>(*this, text, kRobotTimeoutSeconds);
#endif
}

}  // namespace rb::web
