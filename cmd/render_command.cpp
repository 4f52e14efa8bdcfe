#include "render_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "arena_view.h"
#include "exit_codes.h"
#include "headless_run.h"
#include "png_writer.h"
#include "robot_view.h"
#include "svg_writer.h"

namespace rb::cli {

namespace {

struct RenderOptions {
  RunOptions run;
  std::string output;
  int scale = 1;
  bool ascii = false;
  int cols = 100, rows = 37;
  std::string cells = "ascii";
};

enum class Format { Png, Svg, Text };

/// The largest --cols / --rows: far beyond any terminal, small enough to stay fast.
constexpr int kMaxCells = 2000;

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
          return exitcode::kIoError;
        }
        return exitcode::kOk;
      }
      case Format::Png:
        if (render::writePngFile(opts.output, render::composeImage(machine.shownScreen(), robot, opts.scale), error))
          return exitcode::kOk;
        break;
      case Format::Svg: {
        std::string svg = render::renderSvg(canvas, robot, opts.scale,
                                            machine.showsFlip() ? &machine.shownScreen() : nullptr);
        if (render::writeFileBytes(opts.output, svg.data(), svg.size(), error)) return exitcode::kOk;
        break;
      }
    }
  } catch (const std::exception& e) {
    error = "cannot write '" + opts.output + "': " + e.what();
  }
  std::fprintf(stderr, "rb render: %s\n", error.c_str());
  return exitcode::kIoError;
}

int executeRender(const RenderOptions& opts) {
  // Check the command line before running anything: a long run that cannot be saved is waste.
  Format format = Format::Text;
  if (!opts.ascii) {
    if (opts.output.empty()) {
      std::fprintf(stderr, "rb render: name the picture to write with -o OUT (.png or .svg), or use --ascii\n");
      return exitcode::kUsage;
    }
    std::string ext = extensionOf(opts.output);
    if (ext == ".png") {
      format = Format::Png;
    } else if (ext == ".svg") {
      format = Format::Svg;
    } else {
      std::fprintf(stderr, "rb render: cannot tell the format of '%s': the name must end in .png or .svg\n",
                   opts.output.c_str());
      return exitcode::kUsage;
    }
  }

  HeadlessRun run;
  // For a picture, stopping after N steps is a way to choose the moment, not a failure.
  run.stepLimitIsError = false;
  run.keepDisplayList = format == Format::Svg;
  int code = runHeadless("rb render", opts.run, CompileOptions{}, nullptr, nullptr, run);
  if (!run.ran) return code;  // nothing ran (load error, missing file): there is no picture
  if (run.result.status == RunStatus::StepLimit)
    std::fprintf(stderr, "rb render: stopped after %llu steps (--max-steps)\n",
                 static_cast<unsigned long long>(run.result.steps));
  // After a runtime error the picture of the screen at that moment is still written: it often
  // shows what went wrong (where the robot crashed).
  int written = writePicture(opts, format, *run.machine);
  return written != exitcode::kOk ? written : code;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto opts = std::make_shared<RenderOptions>();
  CLI::App* render = app.add_subcommand(
      "render", "Run a program headless and write its final screen as PNG, SVG or text");
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
  addRunLimitOptions(*render, opts->run);
  render->footer(
      "The program runs to its end (or --max-steps) with its printed output discarded (it is on "
      "the screen anyway); then the screen is written with the robot drawn on top (a circle of "
      "its radius and a line toward its heading; in --ascii one glyph: ^ / > \\ v / < \\ or "
      "arrows). Reaching --max-steps is not an error here: the picture is written, a note is "
      "printed and the exit status is 0. After a runtime error or --timeout the picture of that "
      "moment is still written and the exit status is 70. Exit status: 0 written, 64 bad usage "
      "(also an OUT that is not .png or .svg), 65 the program has errors (nothing written), 66 "
      "file not found, 70 runtime error or timeout (picture written), 74 OUT cannot be written. "
      "Manual: man rb-render.");
  render->callback([opts, &exitCode] { exitCode = executeRender(*opts); });
}

}  // namespace rb::cli
