#include "render_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <unistd.h>

#include "run_command.h"
#include "animation.h"
#include "arena_view.h"
#include "exit_codes.h"
#include "headless_run.h"
#include "png_writer.h"
#include "robot_view.h"
#include "svg_writer.h"

namespace rb::cli {

namespace {

struct RenderOptions {
  run::RunOptions run;
  std::string output;
  int scale = 1;
  bool ascii = false;
  int cols = 100, rows = 37;
  std::string cells = "ascii";
  std::string animate;  ///< --animate OUT: a replay of the run (.gif, .svg, .html)
  render::AnimationOptions animation;
  std::optional<double> duration;
  std::optional<uint64_t> every;
  bool noGlide = false;  ///< --no-glide
};

enum class Format { Png, Svg, Text };

/// The largest --cols / --rows: far beyond any terminal, small enough to stay fast.
constexpr int kMaxCells = 2000;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// A number option's valid range, in the message a bad value gets ("--fps: must be a number
/// from 0.1 to 100, not '0'"); `whole`: whole numbers only.
CLI::Validator numberFrom(double lo, double hi, bool whole = false) {
  const std::string range = std::isinf(hi) ? number(lo) + " or more" : number(lo) + " to " + number(hi);
  return CLI::Validator(
      [lo, hi, whole, range](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        const bool ok = !text.empty() && end && *end == '\0' && v >= lo && v <= hi && (!whole || v == std::floor(v));
        return ok ? "" : std::string("must be a ") + (whole ? "whole number" : "number") + (std::isinf(hi) ? ", " : " from ") +
                             range + ", not '" + text + "'";
      },
      range);
}

/// OUT's extension, lower-cased (".PNG" is as good as ".png").
std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

render::CellMode cellMode(const std::string& name) {
  if (name == "half") return render::CellMode::HalfBlock;
  if (name == "braille") return render::CellMode::Braille;
  return render::CellMode::Ascii;
}

/// Writes the picture of the machine's screen as a viewer sees it (with flip on, the screen at the
/// last flip); returns 0 or kIoError (message printed).
int writePicture(const RenderOptions& opts, Format format, const Machine& machine) {
  const render::RobotView robot = render::robotView(machine);
  const Canvas& canvas = machine.canvas();
  std::string error;
  try {
    switch (format) {
      case Format::Text: {
        render::ArenaOptions view;
        view.cols = opts.cols;
        view.rows = opts.rows;
        view.mode = cellMode(opts.cells);
        std::string text = render::frameText(render::renderArena(machine.shownScreen(), canvas.background(), robot, view));
        if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
          std::fprintf(stderr, "rb render: cannot write to standard output\n");
          return run::exitcode::kIoError;
        }
        return run::exitcode::kOk;
      }
      case Format::Png:
        if (render::writePngFile(opts.output, render::composeImage(machine.shownScreen(), robot, opts.scale), error))
          return run::exitcode::kOk;
        break;
      case Format::Svg: {
        std::string svg = render::renderSvg(canvas, robot, opts.scale,
                                            machine.showsFlip() ? &machine.shownScreen() : nullptr);
        if (render::writeFileBytes(opts.output, svg.data(), svg.size(), error)) return run::exitcode::kOk;
        break;
      }
    }
  } catch (const std::exception& e) {
    error = "cannot write '" + opts.output + "': " + e.what();
  }
  std::fprintf(stderr, "rb render: %s\n", error.c_str());
  return run::exitcode::kIoError;
}

/// Why OUT cannot be written, found before the run ("" when it looks writable): its folder is
/// missing or not writable, or OUT is a folder.
std::string unwritable(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir, ec)) return "no such folder '" + dir.string() + "'";
  if (fs::is_directory(path, ec)) return "it is a folder";
  if (::access(dir.c_str(), W_OK) != 0) return std::strerror(errno);
  return "";
}

/// Feeds a recording from the machine's robot events (sensor readings).
class RecordingObserver : public RobotObserver {
 public:
  explicit RecordingObserver(Recording& r) : rec_(r) {}
  void robotEvent(const RobotEvent& e) override { rec_.robotEvent(e); }

 private:
  Recording& rec_;
};

int executeRender(const RenderOptions& opts) {
  // Check the command line before running anything: a long run that cannot be saved is waste.
  Format format = Format::Text;
  const bool animate = !opts.animate.empty();
  if (animate) {
    if (render::animationFormat(opts.animate).empty()) {
      std::fprintf(stderr, "rb render: --animate: cannot tell the format of '%s': the name must end in .gif, .svg or .html\n",
                   opts.animate.c_str());
      return run::exitcode::kUsage;
    }
    if (std::string why = unwritable(opts.animate); !why.empty()) {
      std::fprintf(stderr, "rb render: --animate: cannot write '%s': %s\n", opts.animate.c_str(), why.c_str());
      return run::exitcode::kIoError;
    }
  }
  const bool picture = opts.ascii || !opts.output.empty();
  if (!opts.ascii && !(animate && opts.output.empty())) {
    if (opts.output.empty()) {
      std::fprintf(stderr, "rb render: name the picture to write with -o OUT (.png or .svg), the animation with "
                           "--animate OUT (.gif, .svg or .html), or use --ascii\n");
      return run::exitcode::kUsage;
    }
    std::string ext = extensionOf(opts.output);
    if (ext == ".png") {
      format = Format::Png;
    } else if (ext == ".svg") {
      format = Format::Svg;
    } else {
      std::fprintf(stderr, "rb render: cannot tell the format of '%s': the name must end in .png or .svg\n",
                   opts.output.c_str());
      return run::exitcode::kUsage;
    }
  }

  run::HeadlessRun run;
  run.outputs = {opts.output, opts.animate};
  // For a picture, stopping after N steps is a way to choose the moment, not a failure.
  run.stepLimitIsError = false;
  run.keepDisplayList = picture && format == Format::Svg;
  // An animation records the run: every statement (compiled with line tracing for the hook),
  // the robot's sensors, the output and the lines input read. The recording keeps within its
  // memory budget however long the run (core/machine/recording.h).
  CompileOptions compile;
  compile.lineTracing = animate;
  std::optional<Recording> recording;
  std::optional<RecordingObserver> observer;
  std::function<void(SourceLoc)> onLine;
  if (animate) {
    recording.emplace();
    observer.emplace(*recording);
    run.onCopy = [&recording](std::string_view text) { recording->output(text); };
    run.onInput = [&recording](const run::HeadlessHost::InputSpan& s) { recording->input(s.line); };
    run.afterRun = [&recording](run::HeadlessRun& r) { recording->finish(*r.machine, r.result); };
    onLine = [&recording, &run](SourceLoc loc) { recording->statement(loc, *run.machine); };
  }
  int code = run::runHeadless("rb render", opts.run, compile, nullptr, observer ? &*observer : nullptr, run,
                              std::move(onLine));
  if (!run.ran) return code;  // nothing ran (load error, missing file): there is no picture
  if (run.result.status == RunStatus::StepLimit)
    std::fprintf(stderr, "rb render: stopped after %llu steps (--max-steps)\n",
                 static_cast<unsigned long long>(run.result.steps));
  // After a runtime error the picture of the screen at that moment is still written: it often
  // shows what went wrong (where the robot crashed). So is the animation, which ends there.
  int written = picture ? writePicture(opts, format, *run.machine) : run::exitcode::kOk;
  if (animate && recording && recording->finished()) {
    render::PlayerSource source;
    const SourceSet& sources = run.loaded.program->sources;
    if (sources.size() > 0) {
      source.name = std::filesystem::path(sources.file(0).name()).filename().string();
      source.text = sources.file(0).text();
    }
    render::AnimationOptions options = opts.animation;
    options.scale = opts.scale;
    options.duration = opts.duration;
    options.every = opts.every;
    options.glide = !opts.noGlide;
    std::string error;
    if (!render::writeAnimation(opts.animate, *recording, source, options, error)) {
      std::fprintf(stderr, "rb render: --animate: %s\n", error.c_str());
      written = run::exitcode::kIoError;
    }
  }
  return written != run::exitcode::kOk ? written : code;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto opts = std::make_shared<RenderOptions>();
  CLI::App* render = app.add_subcommand(
      "render", "Run a program headless and write its final screen as PNG, SVG or text, or a replay of the run (GIF, SVG, HTML)");
  if (!withOptions) return;
  render->add_option("file", opts->run.file, "Program file (- reads the program from standard input)")
      ->required();
  CLI::Option* output = render->add_option(
      "-o,--output", opts->output,
      "Picture to write: OUT.png (the screen's pixels) or OUT.svg (vector shapes; an embedded "
      "image after floodFill and the like); the format comes from the extension")
      ->type_name("OUT");
  render->add_option("--scale", opts->scale,
                     "Scale the picture by N (1.." + std::to_string(render::kMaxScale) +
                         ", default 1): PNG pixels are repeated, SVG width and height multiplied")
      ->type_name("N")
      ->check(CLI::Range(1, render::kMaxScale));
  CLI::Option* ascii = render->add_flag(
      "--ascii", opts->ascii,
      "Print the screen as characters on standard output instead of writing a picture");
  render->add_option("--cols", opts->cols, "Columns of the --ascii view (default 100)")
      ->type_name("N")
      ->check(CLI::Range(1, kMaxCells));
  render->add_option("--rows", opts->rows, "Rows of the --ascii view (default 37)")
      ->type_name("N")
      ->check(CLI::Range(1, kMaxCells));
  render->add_option("--cells", opts->cells,
                     "Characters of the --ascii view: ascii (density . : + * #, default), half "
                     "(UTF-8 half blocks, two pixel rows per cell) or braille (UTF-8, 2 x 4 dots per cell)")
      ->type_name("MODE")
      ->check(CLI::IsMember({"ascii", "half", "braille"}));
  output->excludes(ascii);
  CLI::Option* animate = render->add_option(
      "--animate", opts->animate,
      "Also write a replay of the run: OUT.gif (an animated GIF that loops), OUT.svg (an animated "
      "SVG, no script) or OUT.html (a page with a player: play, pause, speed, a timeline, step by "
      "step, the source line, the output, the robot's pose and sensors); the format comes from "
      "the extension. With -o or --ascii both are written from the one run")
      ->type_name("OUT");
  render->add_option("--fps", opts->animation.fps,
                     "Frames per second of the replay (0.1 to 100, default 10)")
      ->type_name("N")
      ->check(numberFrom(render::kMinFps, render::kMaxFps))
      ->needs(animate);
  CLI::Option* duration = render->add_option(
      "--duration", opts->duration,
      "Play the whole run in S seconds (0.01 to 3600): frames at evenly spaced statements, --fps "
      "of them a second (at most 2000)")
      ->type_name("S")
      ->check(numberFrom(1 / render::kMaxFps, render::kMaxDuration))
      ->needs(animate);
  CLI::Option* every = render->add_option(
      "--every", opts->every,
      "One frame every N statements (at most 2000 frames, then evenly sampled) instead of one per "
      "visible change")
      ->type_name("N")
      ->check(numberFrom(1, 1e18, true))
      ->needs(animate);
  every->excludes(duration);
  render->add_flag("--autoplay", opts->animation.autoplay,
                   "The HTML player starts playing once it is opened and in view (not when the viewer "
                   "asks for reduced motion); its 'play on opening' box, once ticked or cleared, "
                   "decides instead on that computer")
      ->needs(animate);
  render->add_flag("--no-glide", opts->noGlide,
                   "One frame per visible change only: long moves and turns are not shown in frames "
                   "of their own")
      ->needs(animate);
  render->add_option("--hold", opts->animation.hold,
                     "Seconds the GIF shows its last frame before it loops (0 to 600, default 2)")
      ->type_name("S")
      ->check(numberFrom(0, render::kMaxHold))
      ->needs(animate);
  addRunLimitOptions(*render, opts->run);
  render->footer(
      "The program runs to its end (or --max-steps) with its printed output discarded (it is on "
      "the screen anyway); then the screen is written with the robot drawn on top (a circle of "
      "its radius and a line toward its heading; in --ascii one glyph: ^ / > \\ v / < \\ or "
      "arrows). Reaching --max-steps is not an error here: the picture is written, a note is "
      "printed and the exit status is 0. After a runtime error or --timeout the picture of that "
      "moment is still written and the exit status is 70. --animate records the run and writes "
      "its replay: by default one frame per recorded statement after which the picture changed "
      "(at most 2000, evenly sampled), --fps a second; the last frame is the picture -o writes. "
      "Exit status: 0 written, 64 bad usage "
      "(also an OUT that is not .png or .svg, an --animate OUT that is not .gif, .svg or .html), "
      "65 the program has errors (nothing written), 66 "
      "file not found, 70 runtime error or timeout (picture written), 74 OUT cannot be written. "
      "Manual: man rb-render.");
  render->callback([opts, &exitCode] { exitCode = executeRender(*opts); });
}

}  // namespace rb::cli
