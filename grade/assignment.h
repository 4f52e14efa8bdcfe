#pragma once
// The assignment file a teacher writes once for a whole class (TOML, docs/teaching.md): the
// input every program gets, the limits of a run, the reference solution and the checks.

#include <cstdint>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "geometry.h"

namespace rb::grade {

struct Check {
  enum Kind {
    Output,          ///< the output, exactly or line by line against patterns
    NoError,         ///< the run finishes: no runtime error, no limit reached
    NoCrash,         ///< the robot never crashes into an obstacle
    Clean,           ///< rb check finds no errors (and no warnings unless allowed)
    EndsIn,          ///< the robot ends inside a region
    Visits,          ///< the robot passes points (in order)
    Trail,           ///< the pen trail lies close to a reference path
    Screen,          ///< the final screen is close to a reference picture
    SolutionOutput,  ///< the same output as the solution
    SolutionTrail,   ///< a trail close to the solution's
    SolutionScreen,  ///< a final screen close to the solution's
  };
  Kind kind = NoError;
  std::string name;        ///< shown in reports; the kind's name unless the file names it
  double points = 1;       ///< weight in the grade book
  uint32_t line = 0;       ///< where the check is in the assignment file

  // Output: `text` exactly, or one pattern per line.
  std::optional<std::string> text;
  std::vector<std::string> patterns;
  std::vector<std::regex> regexes;
  // Clean
  bool allowWarnings = false;
  std::string target;      ///< "rb9": also rb check --target rb9's warnings
  // EndsIn
  Region region;
  // Visits
  std::vector<P2> targets;
  bool inOrder = true;
  // Trail (reference), Visits, EndsIn, the solution and screen checks: how close is close.
  Polylines reference;
  double tolerance = 0;    ///< pixels, or a share of pixels (0..1) for the screen checks
  // Screen
  std::string picture;     ///< absolute path of the reference PNG
};

/// The kind's name as the assignment file writes it ("solution-trail").
const char* kindName(Check::Kind kind);

struct Assignment {
  std::string path;                     ///< the assignment file
  std::string title;
  std::optional<std::string> solution;  ///< absolute path of the reference solution
  std::vector<uint64_t> seeds{1};       ///< each program runs once per seed
  uint64_t maxSteps = 10'000'000;       ///< statements per run (0: no limit)
  double timeout = 10;                  ///< seconds of real time per run
  uint64_t memoryMb = 512;              ///< memory per run
  std::string events;                   ///< absolute path of an events script, or ""
  std::string keys;
  std::vector<std::string> stdinLines;
  std::vector<Check> checks;

  bool needsSolution() const;
  /// A check compares final screens.
  bool needsScreen() const;
  /// The largest points total.
  double maxPoints() const;
};

/// Reads and checks an assignment file. Relative paths in it (solution, events, pictures) are
/// relative to the file's folder. nullopt with `error` ("FILE:LINE:COL: what is wrong") when the
/// file cannot be read or is not a valid assignment.
std::optional<Assignment> loadAssignment(const std::string& path, std::string& error);

}  // namespace rb::grade
