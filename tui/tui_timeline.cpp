#include "tui_timeline.h"

#include <algorithm>
#include <cmath>

namespace rb::tui {

PastStep pastStep(const Recording& rec, size_t index) {
  PastStep p;
  const RecordedStep& s = rec.steps()[index];
  p.step = s;
  std::vector<Colour> pixels = rec.screen(s.frame);
  p.screen.assign(pixels.begin(), pixels.end());
  p.robot.visible = s.located;
  p.robot.x = s.x;
  p.robot.y = s.y;
  p.robot.heading = s.heading;
  p.robot.radius = s.radius;
  p.robot.colour = s.robotColour;
  // The events are in the order of their steps, each with the statement that made it: the
  // last rRange read by a statement before this one.
  const std::vector<RecordedEvent>& events = rec.events();
  auto end = std::lower_bound(events.begin(), events.end(), s.step,
                              [](const RecordedEvent& e, uint64_t step) { return e.step < step; });
  for (auto it = end; it != events.begin();) {
    --it;
    if (it->kind == RecordedEvent::Sensor && it->what == "rRange") {
      p.range = it->value;
      break;
    }
  }
  return p;
}

size_t jumpFrom(const Recording& rec, size_t index, double fraction) {
  const std::vector<RecordedStep>& steps = rec.steps();
  if (steps.empty()) return 0;
  index = std::min(index, steps.size() - 1);
  double whole = static_cast<double>(steps.back().step);
  double span = std::max(1.0, std::round(whole * std::fabs(fraction)));
  uint64_t here = steps[index].step;
  auto by = static_cast<uint64_t>(span);
  if (fraction < 0) {
    size_t to = rec.stepAt(here > by ? here - by : 0);
    return to >= index && index > 0 ? index - 1 : to;
  }
  size_t to = rec.stepAt(here + by);
  if (to <= index && index + 1 < steps.size()) to = index + 1;
  return std::min(to, steps.size() - 1);
}

std::string grouped(uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string stepName(const RecordedStep& s) {
  if (!s.loc.valid()) return "the end";
  return "step " + grouped(s.step + 1);
}

std::string timelineRule(int width, const std::string& label, size_t at, size_t count, int& barCol,
                         int& barWidth) {
  constexpr int kMaxBar = 50;
  std::string line = "-- " + label + " [";
  int room = width - static_cast<int>(line.size()) - 4;  // "] --"
  barWidth = std::min(room, kMaxBar);
  if (barWidth < 5) {
    barWidth = 0;
    barCol = 0;
    line = "-- " + label + " ";
  } else {
    barCol = static_cast<int>(line.size());
    int pos = count <= 1 ? barWidth - 1
                         : static_cast<int>(static_cast<uint64_t>(std::min(at, count - 1)) *
                                            static_cast<uint64_t>(barWidth - 1) / (count - 1));
    for (int i = 0; i < barWidth; ++i) line += i < pos ? '#' : i == pos ? '|' : '.';
    line += "] ";
  }
  line.resize(static_cast<size_t>(std::max(width, 0)), '-');
  return line;
}

size_t stepAtColumn(int col, int barCol, int barWidth, size_t count) {
  if (count <= 1 || barWidth <= 1) return 0;
  int c = std::clamp(col - barCol, 0, barWidth - 1);
  return static_cast<size_t>(std::lround(static_cast<double>(c) * static_cast<double>(count - 1) /
                                         (barWidth - 1)));
}

std::vector<std::string_view> lastLines(std::string_view text, size_t maxLines) {
  std::vector<std::string_view> out;
  size_t end = text.size();
  if (end > 0 && text[end - 1] == '\n') --end;  // the last line ended: nothing after it
  if (end == 0 && text.empty()) return out;
  while (out.size() < maxLines) {
    size_t nl = end == 0 ? std::string_view::npos : text.rfind('\n', end - 1);
    size_t begin = nl == std::string_view::npos ? 0 : nl + 1;
    out.push_back(text.substr(begin, end - begin));
    if (nl == std::string_view::npos) break;
    end = nl;
  }
  std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace rb::tui
