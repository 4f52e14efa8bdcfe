#include "machine/recording.h"

#include <algorithm>

namespace rb {

namespace {
constexpr size_t kScreenPixels = static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight;
}  // namespace

std::vector<ScreenRun> screenRuns(const Colour* pixels, size_t count) {
  std::vector<ScreenRun> runs;
  for (size_t i = 0; i < count;) {
    Colour c = pixels[i];
    size_t j = i + 1;
    while (j < count && pixels[j] == c) ++j;
    runs.push_back({static_cast<uint32_t>(j - i), c});
    i = j;
  }
  return runs;
}

std::vector<Colour> screenFromRuns(const std::vector<ScreenRun>& runs, size_t count) {
  std::vector<Colour> out;
  out.reserve(count);
  for (const ScreenRun& r : runs) {
    size_t n = std::min<size_t>(r.count, count - out.size());
    out.insert(out.end(), n, r.colour);
  }
  out.resize(count, colours::kWhite);
  return out;
}

RecordedStep Recording::stateOf(SourceLoc loc, const Machine& machine, uint64_t step) const {
  RecordedStep s;
  s.step = step;
  s.loc = loc;
  const Robot& robot = machine.robot();
  s.located = robot.located();
  s.pen = robot.penDown();
  s.x = robot.pose().pos.x();
  s.y = robot.pose().pos.y();
  s.heading = robot.pose().heading;
  s.radius = robot.radius();
  s.robotColour = robot.colour();
  s.frame = frames_.empty() ? 0 : static_cast<uint32_t>(frames_.size() - 1);
  s.output = outputBytes_;
  return s;
}

RecordedFrame Recording::encode(const Colour* pixels, const std::vector<Colour>& before, uint64_t step,
                                bool full) const {
  RecordedFrame f;
  f.step = step;
  f.full = full || before.size() != kScreenPixels;
  if (f.full) {
    f.runs = screenRuns(pixels, kScreenPixels);
    return f;
  }
  for (size_t i = 0; i < kScreenPixels;) {
    size_t j = i;
    if (pixels[i] == before[i]) {
      while (j < kScreenPixels && pixels[j] == before[j]) ++j;
      f.runs.push_back({static_cast<uint32_t>(j - i), kSameColour});
    } else {
      Colour c = pixels[i];
      while (j < kScreenPixels && pixels[j] == c && pixels[j] != before[j]) ++j;
      f.runs.push_back({static_cast<uint32_t>(j - i), c});
    }
    i = j;
  }
  return f;
}

namespace {
size_t sizeOf(const RecordedFrame& f) { return f.runs.size() * sizeof(ScreenRun) + sizeof(RecordedFrame); }

/// Applies a frame to the screen before it.
void applyFrame(const RecordedFrame& f, std::vector<Colour>& screen) {
  size_t at = 0;
  for (const ScreenRun& r : f.runs) {
    size_t n = std::min<size_t>(r.count, screen.size() - at);
    if (r.colour != kSameColour) std::fill(screen.begin() + static_cast<long>(at), screen.begin() + static_cast<long>(at + n), r.colour);
    at += n;
  }
}
}  // namespace

uint64_t Recording::shownVersion(const Machine& machine) {
  return machine.showsFlip() ? machine.flips | uint64_t{1} << 63 : machine.canvas().version();
}

void Recording::keyframe(Machine& machine, uint64_t step) {
  // What a viewer sees: with flip on, the screen at the last flip (as rb render and the live
  // view show it), else the canvas.
  Canvas& canvas = machine.canvas();
  const Pixels& pixels = machine.shownScreen();
  if (pixels.size() < kScreenPixels) return;
  PixelBox box = canvas.takeDamage();
  // The canvas's damage says nothing of a flip's screen: compare all of it.
  bool flipShown = machine.showsFlip();
  if (flipShown || lastShownFlip_) box = PixelBox{0, 0, Canvas::kWidth - 1, Canvas::kHeight - 1};
  lastShownFlip_ = flipShown;
  bool full = last_.size() != kScreenPixels || sinceFull_ >= std::max(lastFull_, kFullAfter);
  if (full) {
    frames_.push_back(encode(pixels.data(), {}, step, true));
    last_.assign(pixels.begin(), pixels.begin() + static_cast<long>(kScreenPixels));
  } else {
    // Only the box where pixels changed is compared; the rest is as before.
    RecordedFrame f;
    f.step = step;
    auto same = [&f](size_t n) {
      if (n == 0) return;
      if (!f.runs.empty() && f.runs.back().colour == kSameColour) f.runs.back().count += static_cast<uint32_t>(n);
      else f.runs.push_back({static_cast<uint32_t>(n), kSameColour});
    };
    size_t pos = 0;
    if (!box.empty()) {
      int x0 = std::max(0, box.x0), x1 = std::min(Canvas::kWidth - 1, box.x1);
      int y0 = std::max(0, box.y0), y1 = std::min(Canvas::kHeight - 1, box.y1);
      for (int y = y0; y <= y1 && x0 <= x1; ++y) {
        size_t begin = static_cast<size_t>(y) * Canvas::kWidth + static_cast<size_t>(x0);
        size_t end = static_cast<size_t>(y) * Canvas::kWidth + static_cast<size_t>(x1) + 1;
        same(begin - pos);
        for (size_t i = begin; i < end;) {
          size_t j = i;
          if (pixels[i] == last_[i]) {
            while (j < end && pixels[j] == last_[j]) ++j;
            same(j - i);
          } else {
            Colour c = pixels[i];
            while (j < end && pixels[j] == c && pixels[j] != last_[j]) last_[j++] = c;
            f.runs.push_back({static_cast<uint32_t>(j - i), c});
          }
          i = j;
        }
        pos = end;
      }
    }
    same(kScreenPixels - pos);
    frames_.push_back(std::move(f));
  }
  frameBytes_ += sizeOf(frames_.back());
  shownVersion_ = shownVersion(machine);
  lastFrameStep_ = step;
  thinFrames();
}

void Recording::statement(SourceLoc loc, Machine& machine) {
  uint64_t step = total_++;
  Canvas& canvas = machine.canvas();
  if (frames_.empty()) canvas.trackDamage(true);
  bool changed = frames_.empty() || shownVersion(machine) != shownVersion_;
  if (changed && (frames_.empty() || step - lastFrameStep_ >= frameStride_)) keyframe(machine, step);
  if (step % stepStride_ != 0) return;
  steps_.push_back(stateOf(loc, machine, step));
  if (stepBytes() > budget_ * 3 / 8) thinSteps();
}

void Recording::output(std::string_view text) {
  outputBytes_ += text.size();
  size_t cap = std::min(kOutputCap, budget_ / 16);
  if (output_.size() < cap) output_.append(text.substr(0, cap - output_.size()));
}

void Recording::input(std::string_view line) {
  uint64_t step = total_ ? total_ - 1 : 0;
  if (eventBytes_ > budget_ / 16) return;  // a program that reads input without end
  events_.push_back({step, RecordedEvent::Input, std::string(line.substr(0, 4096)), 0});
  eventBytes_ += sizeof(RecordedEvent) + events_.back().what.size();
}

void Recording::robotEvent(const RobotEvent& e) {
  if (e.kind != RobotEvent::Sensor || !e.value) return;
  uint64_t step = total_ ? total_ - 1 : 0;
  if (step % stepStride_ != 0) return;
  events_.push_back({step, RecordedEvent::Sensor, std::string(e.command), *e.value});
  eventBytes_ += sizeof(RecordedEvent) + events_.back().what.size();
  if (eventBytes_ > budget_ / 16) thinSteps();
}

void Recording::finish(Machine& machine, const RunResult& result) {
  if (finished_) return;
  finished_ = true;
  status_ = result.status;
  error_ = result.error;
  if (frames_.empty() || shownVersion(machine) != shownVersion_) {
    uint64_t stride = frameStride_;
    frameStride_ = 1;  // the last screen is always kept
    keyframe(machine, total_);
    frameStride_ = std::max(frameStride_, stride);
  }
  SourceLoc end;
  steps_.push_back(stateOf(end, machine, total_));
  steps_.back().frame = static_cast<uint32_t>(frames_.size() - 1);
}

void Recording::thinSteps() {
  stepStride_ *= 2;
  std::erase_if(steps_, [this](const RecordedStep& s) { return s.step % stepStride_ != 0; });
  std::erase_if(events_, [this](const RecordedEvent& e) {
    return e.kind == RecordedEvent::Sensor && e.step % stepStride_ != 0;
  });
  eventBytes_ = 0;
  for (const RecordedEvent& e : events_) eventBytes_ += sizeof(RecordedEvent) + e.what.size();
  steps_.shrink_to_fit();
}

namespace {
/// One frame that does what `before` then `after` do (both cover the whole screen): a pixel
/// takes after's colour, else before's, else stays as it was. Linear in their runs.
RecordedFrame merged(const RecordedFrame& before, const RecordedFrame& after) {
  RecordedFrame out;
  out.step = after.step;
  out.full = before.full || after.full;
  auto push = [&out](uint32_t n, Colour c) {
    if (n == 0) return;
    if (!out.runs.empty() && out.runs.back().colour == c) out.runs.back().count += n;
    else out.runs.push_back({n, c});
  };
  size_t i = 0, j = 0;
  uint32_t leftA = before.runs.empty() ? 0 : before.runs[0].count, leftB = after.runs.empty() ? 0 : after.runs[0].count;
  while (i < before.runs.size() && j < after.runs.size()) {
    uint32_t n = std::min(leftA, leftB);
    Colour c = after.runs[j].colour != kSameColour ? after.runs[j].colour : before.runs[i].colour;
    push(n, c);
    leftA -= n;
    leftB -= n;
    if (leftA == 0 && ++i < before.runs.size()) leftA = before.runs[i].count;
    if (leftB == 0 && ++j < after.runs.size()) leftB = after.runs[j].count;
  }
  return out;
}
}  // namespace

void Recording::thinFrames() {
  if (frameBytes_ <= budget_ * 3 / 8) return;
  // Down to half of that at least, so that the next thinning is as far off as this one was after
  // the last (a frame's bytes do not halve with their number: merged changes are bigger).
  while (frameBytes_ > budget_ * 3 / 16 && frames_.size() >= 3) thinFramesOnce();
}

void Recording::thinFramesOnce() {
  frameStride_ *= 2;
  // Keep the first, then each frame at least a stride after the last kept one; the newest stays
  // (it is the screen now). A dropped frame's changes go into the next kept frame, which is then
  // made whole or a change again as its place asks (by the same rule as keyframe(): kFullAfter).
  std::vector<uint32_t> newIndex(frames_.size());
  std::vector<RecordedFrame> kept;
  std::optional<RecordedFrame> pending;
  std::vector<Colour> screen(kScreenPixels, colours::kWhite);  // what the last kept frame shows
  size_t since = 0, fullSize = 0;  // as sinceFull_ and lastFull_, for the kept frames
  frameBytes_ = 0;
  for (size_t i = 0; i < frames_.size(); ++i) {
    bool keep = kept.empty() || i + 1 == frames_.size() || frames_[i].step - kept.back().step >= frameStride_;
    RecordedFrame f = pending ? merged(*pending, frames_[i]) : std::move(frames_[i]);
    pending.reset();
    if (!keep) {
      pending = std::move(f);
      newIndex[i] = static_cast<uint32_t>(kept.size() - 1);
      continue;
    }
    // Whole where the rule wants a checkpoint; a kept frame made whole by a dropped whole frame
    // becomes changes again elsewhere, so whole frames keep their share of the memory.
    bool wantFull = kept.empty() || since >= std::max(fullSize, kFullAfter);
    if (f.full && !wantFull) {
      std::vector<Colour> now = screenFromRuns(f.runs, kScreenPixels);
      f = encode(now.data(), screen, f.step, false);
      screen = std::move(now);
    } else {
      applyFrame(f, screen);
      if (wantFull && !f.full) f = encode(screen.data(), {}, f.step, true);
    }
    if (f.full) {
      fullSize = sizeOf(f);
      since = 0;
    } else {
      since += sizeOf(f);
    }
    frameBytes_ += sizeOf(f);
    kept.push_back(std::move(f));
    newIndex[i] = static_cast<uint32_t>(kept.size() - 1);
  }
  frames_ = std::move(kept);
  frames_.shrink_to_fit();
  sinceFull_ = since;
  lastFull_ = fullSize;
  for (RecordedStep& s : steps_) s.frame = newIndex[std::min<size_t>(s.frame, newIndex.size() - 1)];
}

std::vector<Colour> Recording::screen(size_t frame) const {
  std::vector<Colour> out(kScreenPixels, colours::kWhite);
  if (frame >= frames_.size()) return out;
  size_t first = frame;
  while (first > 0 && !frames_[first].full) --first;
  for (size_t i = first; i <= frame; ++i) applyFrame(frames_[i], out);
  return out;
}

size_t Recording::stepAt(uint64_t step) const {
  auto it = std::upper_bound(steps_.begin(), steps_.end(), step,
                             [](uint64_t s, const RecordedStep& r) { return s < r.step; });
  return it == steps_.begin() ? 0 : static_cast<size_t>(it - steps_.begin() - 1);
}

}  // namespace rb
