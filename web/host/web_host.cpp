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
#include "lang/value.h"
#include "machine/watch.h"
#include "robot/protocol.h"
#include "robot/reply_check.h"

// The page's side of each call: Module.rbHooks, set by web/rblive.js (live runs) and web/rb.js
// (headless runs) for each run. The waiting ones are async in the Asyncify build (rbcore: the
// run is suspended until the hook's promise settles) and plain calls in rbcore_fast, whose
// hooks wait with Atomics.wait; their JavaScript is the same for both (a hook's answer, or a
// promise of it, goes through Module.rbThen).
#ifdef RB_NO_ASYNC
#define RB_WAIT_JS EM_JS
#else
#define RB_WAIT_JS EM_ASYNC_JS
#endif
// clang-format off
EM_JS(void, rb_js_output, (const char* text, int size), { Module.rbHooks.output(UTF8ToString(text, size)); });
EM_JS(int, rb_js_stopped, (), { return Module.rbHooks.stopped() ? 1 : 0; });
EM_JS(double, rb_js_step_ms, (), { return Module.rbHooks.stepMs(); });
EM_JS(int, rb_js_stepping, (), { return Module.rbHooks.stepping() ? 1 : 0; });
// Paused: `info` (JSON: where the run stands, the variables, the watches) for the page; 1 when
// the page asks for a fresh look (a watch was added), else 0 (go on: resumed, stepped, stopped).
RB_WAIT_JS(int, rb_js_pause, (const char* info, int size), {
  return Module.rbHooks.pause(UTF8ToString(info, size));
});
// The page's watch expressions, one a line (malloc'ed).
EM_JS(char*, rb_js_watches, (), {
  const text = Module.rbHooks.watches ? Module.rbHooks.watches() : "";
  const size = lengthBytesUTF8(text) + 1;
  const p = _malloc(size);
  stringToUTF8(text, p, size);
  return p;
});
// The state the page's text alternative of the screen reads (WebHost::stateJson).
EM_JS(void, rb_js_state, (const char* json, int size), { if (Module.rbHooks.state) Module.rbHooks.state(UTF8ToString(json, size)); });
EM_JS(void, rb_js_frame, (const uint8_t* rgba, int width, int height), { Module.rbHooks.frame(rgba, width, height); });
EM_JS(void, rb_js_finished, (const char* json, int size), {
  if (Module.rbHooks.finished) Module.rbHooks.finished(UTF8ToString(json, size));
});
// Whether the page has drawn the frames sent so far (frames while the run computes wait for it).
EM_JS(int, rb_js_frame_wanted, (), { return !Module.rbHooks.frameWanted || Module.rbHooks.frameWanted() ? 1 : 0; });
EM_JS(void, rb_js_svg, (const char* svg, int size, const uint8_t* rgba, int width, int height), {
  Module.rbHooks.svg(UTF8ToString(svg, size), rgba ? new Uint8ClampedArray(HEAPU8.subarray(rgba, rgba + width * height * 4)) : null,
                     width, height);
});
RB_WAIT_JS(void, rb_js_yield, (double ms), { return Module.rbHooks.yield(ms); });
RB_WAIT_JS(char*, rb_js_input_line, (const char* prompt), {
  return Module.rbThen(Module.rbHooks.inputLine(UTF8ToString(prompt)), (line) => {
    if (line === null || line === undefined) return 0;
    const size = lengthBytesUTF8(line) + 1;
    const p = _malloc(size);
    stringToUTF8(line, p, size);
    return p;
  });
});
// Web Serial (web/app.js). Open: the page asks the user for a port and opens it; the answer is
// the port's name, or "!" and why not. Send: drops what waits unread, writes the command; 0 when
// the port has gone. Take: waits up to `ms` for `want` bytes in all, then gives what came (at
// most `room`); -1 when the port has gone.
RB_WAIT_JS(char*, rb_js_serial_open, (int port), {
  return Module.rbThen(Module.rbHooks.serialOpen(port), (r) => {
    const text = !r ? '!the page did not answer' : r.error ? '!' + r.error : r.name;
    const size = lengthBytesUTF8(text) + 1;
    const p = _malloc(size);
    stringToUTF8(text, p, size);
    return p;
  });
});
RB_WAIT_JS(int, rb_js_serial_send, (int code, int param), {
  return Module.rbThen(Module.rbHooks.serialSend(code, param), (ok) => (ok ? 1 : 0));
});
RB_WAIT_JS(int, rb_js_serial_take, (int want, double ms, uint8_t* out, int room), {
  return Module.rbThen(Module.rbHooks.serialTake(want, ms, room), (bytes) => {
    if (!bytes) return -1;
    HEAPU8.set(bytes, out);
    return bytes.length;
  });
});
EM_JS(void, rb_js_serial_close, (), { Module.rbHooks.serialClose(); });
EM_JS(int, rb_js_held_key, (), { return Module.rbHooks.heldKey(); });
EM_JS(int, rb_js_take_typed, (), { return Module.rbHooks.takeTyped(); });
EM_JS(void, rb_js_controls, (const char* json, int size), { Module.rbHooks.controls(JSON.parse(UTF8ToString(json, size))); });
RB_WAIT_JS(int, rb_js_wait_key, (), { return Module.rbHooks.waitKey(); });
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
RB_WAIT_JS(void, rb_js_wait_click, (int* out), {
  return Module.rbThen(Module.rbHooks.waitClick(), (c) => {
    HEAP32[out >> 2] = c[0]; HEAP32[(out >> 2) + 1] = c[1]; HEAP32[(out >> 2) + 2] = c[2];
  });
});
RB_WAIT_JS(void, rb_js_message_box, (const char* text, const char* title), {
  return Module.rbHooks.messageBox(UTF8ToString(text), UTF8ToString(title));
});
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
  // Printing can be slow (into a full screen, each line scrolls it): the page is looked at
  // between the checkpoints too.
  if (live_) yieldToPage(false);
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
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() - pausedSeconds_;
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
    present(false);
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
  const bool was = stepping_;
  stepping_ = rb_js_stepping() != 0;
  if (stepping_ && !was) finishStatement_ = false;  // a new Pause stops inside a statement too
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
  finishStatement_ = false;
  pauseAt(loc, "before");
}

void WebHost::pauseAt(SourceLoc loc, const char* where) {
  flushOutput();
  present();
  presentState(true);
  const auto began = std::chrono::steady_clock::now();
  while (!stopRequested()) {
    const std::string info = debugJson(loc, where);
    const int again = rb_js_pause(info.data(), static_cast<int>(info.size()));
    if (rb_js_stopped()) requestStop();
    if (!again) break;
  }
  // The run's clock stands still while paused (as the live terminal view's): a program that
  // times itself, and the --timeout, see only the time it ran.
  pausedSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  finishStatement_ = true;  // a Step from here runs to the next statement
  lastYieldMs_ = lastFrameMs_ = wallSeconds() * 1000;
  afterPage();
}

namespace {

std::string oneLine(std::string_view s) {
  std::string out;
  for (char c : s) out += static_cast<unsigned char>(c) < 32 || c == 127 ? ' ' : c;
  return out;
}

/// A value as the live terminal view's variables pane shows it (tui/tui_panes.cpp's valueText):
/// "-" before it has one, strings in quotes, arrays as [3,4] and their first elements; at
/// most `width` characters.
std::string valueText(const Value& v, size_t width) {
  std::string out;
  switch (v.type()) {
    case VType::Undef: out = "-"; break;
    case VType::Int:
    case VType::Num: out = formatValue(v); break;
    case VType::Str: out = '"' + oneLine(v.str()) + '"'; break;
    case VType::Arr: {
      const ArrObj& a = v.arr();
      out = "[";
      for (size_t i = 0; i < a.dims.size(); ++i) out += (i ? "," : "") + std::to_string(a.dims[i]);
      out += "] ";
      for (size_t i = 0; i < a.items.size() && out.size() <= width; ++i) {
        if (i) out += ", ";
        out += valueText(a.items[i], width);
      }
      break;
    }
  }
  if (out.size() > width) out = out.substr(0, width - 3) + "...";
  return out;
}

}  // namespace

std::string WebHost::debugJson(SourceLoc loc, const char* where) {
  constexpr size_t kWidth = 200;
  std::string out = "{\"line\":" + std::to_string(loc.line) + ",\"where\":";
  render::appendJsonString(out, where);
  std::vector<VariableView> vars;
  if (interpreter_) vars = interpreter_->variables();
  out += ",\"sub\":";
  render::appendJsonString(out, interpreter_ ? interpreter_->runningSub() : std::string_view());
  out += ",\"vars\":[";
  for (size_t i = 0; i < vars.size(); ++i) {
    out += i ? ",{\"name\":" : "{\"name\":";
    render::appendJsonString(out, vars[i].name);
    out += vars[i].local ? ",\"local\":true,\"value\":" : ",\"local\":false,\"value\":";
    render::appendJsonString(out, valueText(*vars[i].value, kWidth));
    out += '}';
  }
  out += "],\"watches\":[";
  char* text = rb_js_watches();
  std::string watches = text ? text : "";
  std::free(text);
  bool first = true;
  for (size_t at = 0; at < watches.size();) {
    size_t end = watches.find('\n', at);
    if (end == std::string::npos) end = watches.size();
    const std::string expr = watches.substr(at, end - at);
    at = end + 1;
    if (expr.find_first_not_of(" \t") == std::string::npos) continue;
    out += first ? "{\"expr\":" : ",{\"expr\":";
    first = false;
    render::appendJsonString(out, expr);
    const Watch watch(expr);
    WatchResult r;
    if (!machine_) r.error = "no program runs";
    else r = watch.evaluate(vars, *machine_);
    if (r.value) {
      out += ",\"value\":";
      render::appendJsonString(out, valueText(*r.value, kWidth));
    } else {
      out += ",\"error\":";
      render::appendJsonString(out, r.error);
    }
    out += '}';
  }
  return out + "]}";
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
    pauseInside();
    return;
  }
  flushOutput();
  // The screen as it is, unless the page has not drawn the frame before (robot motion sleeps
  // every few milliseconds: the page gets frames as fast as it draws them, no faster).
  present(false);
  presentState(false);
  // In pieces, so that a Stop during a long delay ends it within one piece.
  while (sleepDebtMs_ > 0 && !stopRequested()) {
    double piece = std::min(sleepDebtMs_, 50.0);
    double before = wallSeconds() * 1000;
    rb_js_yield(piece);
    sleepDebtMs_ -= wallSeconds() * 1000 - before;
    afterPage();
    pauseInside();
    if (sleepDebtMs_ > 0) present(false);  // a frame the page was not ready for before
  }
  sleepDebtMs_ = 0;
  lastYieldMs_ = lastFrameMs_ = wallSeconds() * 1000;
}

void WebHost::pauseInside() {
  if (stepping_ && !finishStatement_ && !stopRequested() && machine_) pauseAt(machine_->location(), "in");
}

bool WebHost::poll() {
  yieldToPage(false);
  return !stopRequested();
}

void WebHost::animate() {
  yieldToPage(false);
  pauseInside();
}

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
  // RGBA bytes are one little-endian word: 0xAABBGGRR. A colour past the palette is
  // r + 256 * g + 65536 * b already (Colour): it only needs its alpha.
  uint32_t palette[16];
  for (Colour c = 0; c < 16; ++c) palette[c] = rgbaWord(colourToRgb(c));
  rgba_.resize(n);
  uint32_t* o = rgba_.data();
  const Colour* in = pixels.data();
  for (size_t i = 0; i < n; ++i) o[i] = in[i] < 16 ? palette[in[i]] : (in[i] & 0xffffffu) | 0xff000000u;
  return true;
}

uint32_t WebHost::rgbaWord(uint32_t rgb) {
  return 0xff000000u | (rgb & 0xff) << 16 | (rgb & 0xff00) | (rgb >> 16 & 0xff);
}

void WebHost::present(bool force) {
  if (!machine_) return;
  presentControls();
  constexpr int w = Canvas::kWidth, h = Canvas::kHeight;
  // The same screen and robot as the frame before: nothing to send (a long computation draws
  // nothing, and converting the screen costs a millisecond).
  const render::RobotView view = render::robotView(*machine_);
  const Shown now{machine_->canvas().version(), machine_->flips, machine_->showsFlip(), view.visible,
                  view.x, view.y, view.heading, view.radius, view.colour};
  if (now == lastShown_) return;
  // While the program runs, a frame only when the page has drawn the ones before (it draws
  // one a frame of its own): a busy page is not sent frames it would drop.
  if (!force && !rb_js_frame_wanted()) return;
  lastShown_ = now;
  if (!toRgba(machine_->shownScreen())) return;
  // The robot on top, as rb render's picture and the live terminal view draw it.
  const render::RobotImage shape(view);
  const uint32_t robot = rgbaWord(colourToRgb(view.colour));
  if (!shape.empty())
    shape.rasterize(1, w, h, [&](int x, int y) {
      rgba_[static_cast<size_t>(y) * w + static_cast<size_t>(x)] = robot;
    });
  rb_js_frame(reinterpret_cast<const uint8_t*>(rgba_.data()), w, h);
}

void WebHost::finished(const std::string& json) {
  if (live_) rb_js_finished(json.data(), static_cast<int>(json.size()));
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
  rb_js_svg(svg.data(), static_cast<int>(svg.size()), havePixels ? reinterpret_cast<const uint8_t*>(rgba_.data()) : nullptr, Canvas::kWidth,
            Canvas::kHeight);
}

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
    if (stopped()) return {};
    uint8_t room[protocol::kMaxReadReply];
    while (exchange.end == protocol::Exchange::End::Complete) {
      const bool full = exchange.bytes.size() >= static_cast<size_t>(protocol::kReplySize);
      const double left = deadline - host_.wallSeconds() * 1000;
      // Once a reply's worth is in, what came with it at once (a longer reply is a fault).
      const int want = full ? 0 : protocol::kReplySize - static_cast<int>(exchange.bytes.size());
      const int got = rb_js_serial_take(want, full ? 0 : std::clamp(left, 0.0, 50.0), room,
                                        static_cast<int>(protocol::kMaxReadReply - exchange.bytes.size()));
      if (stopped()) return {};  // a Stop ends the wait (the answer is then nothing)
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
  /// The page's Stop, looked at after each call to the page.
  bool stopped() {
    if (rb_js_stopped()) host_.requestStop();
    return host_.stopRequested();
  }
  void setWhileWaiting(std::function<void()> hook) override { whileWaiting_ = std::move(hook); }

 private:
  WebHost& host_;
  std::string name_;
  double timeoutSeconds_;
  bool broken_ = false;
  std::function<void()> whileWaiting_;
};

std::unique_ptr<RobotLink> WebHost::openRobot(int64_t port) {
  if (!live_)
    throw RuntimeError("rCommPort " + std::to_string(port) +
                       ": rb.run drives no real robot; run the program on the page to use a robot over Web Serial");
  flushOutput();
  present();
  char* answer = rb_js_serial_open(static_cast<int>(port));
  std::string text = answer ? answer : "!the page did not answer";
  std::free(answer);
  if (rb_js_stopped()) requestStop();
  if (stopRequested()) throw RuntimeError("rCommPort " + std::to_string(port) + ": the run was stopped");
  if (!text.empty() && text[0] == '!') throw RuntimeError("rCommPort " + std::to_string(port) + ": " + text.substr(1));
  return std::make_unique<WebSerialLink>(*this, text, kRobotTimeoutSeconds);
}

}  // namespace rb::web
