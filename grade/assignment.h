#pragma once
// The assignment file a teacher writes once for a whole class (TOML, docs/teaching.md): the
// input every program gets, the limits of a run, the world it runs in, the reference solution
// and the checks, with their points, dependencies and feedback.

#include <cstdint>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "geometry.h"

namespace re2 {
class RE2;
}

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
    Avoid,           ///< the robot never enters a region, never touches a colour
    Touch,           ///< the robot reaches a region, or touches a colour
    Post,            ///< a teacher's program run after the student's, on the final state
    Efficiency,      ///< statements, robot moves or distance, scored in tiers
    AnyOf,           ///< passes when one of its checks passes
    AllOf,           ///< passes when all of its checks pass
  };
  /// What an efficiency limit counts.
  enum Measure { Statements, Moves, Distance };

  Kind kind = NoError;
  std::string name;        ///< shown in reports; the kind's name unless the file names it
  bool named = false;      ///< the file gave the name (else "ends-in", "ends-in 2", ...)
  double points = 1;       ///< weight in the grade book
  uint32_t line = 0;       ///< where the check is in the assignment file
  uint32_t column = 0;

  // For every kind.
  bool required = false;   ///< when it fails, every other check scores 0
  std::string after;       ///< checked only when the check of this name passed
  std::string hint;        ///< shown under its failure
  bool hidden = false;     ///< a student's report says only that a hidden check failed
  /// Efficiency on top of the check: at most this many statements / robot moves / pixels.
  std::optional<double> maxStatements, maxMoves, maxDistance;

  // Output: `text` exactly, or one pattern per line.
  std::optional<std::string> text;
  std::vector<std::string> patterns;
  /// RE2, so that matching takes time linear in the line: no teacher's pattern and no student's
  /// output can stall the class (a nested quantifier backtracks for ever in a backtracking engine).
  std::vector<std::shared_ptr<const re2::RE2>> regexes;
  bool prompts = false;    ///< Output, SolutionOutput: compare input's prompts and echo too
  // Clean
  bool allowWarnings = false;
  std::string target;      ///< "rb9": also rb check --target rb9's warnings
  // EndsIn, Avoid, Touch: regions (EndsIn has exactly one).
  std::vector<record::Region> regions;
  // Avoid, Touch: colours as 0xRRGGBB, with the names the file gave them.
  std::vector<uint32_t> colours;
  std::vector<std::string> colourNames;
  // Visits
  std::vector<record::P2> targets;
  bool inOrder = true;
  // Trail (reference), Visits, the solution and screen checks: how close is close.
  record::Polylines reference;
  double tolerance = 0;    ///< pixels, or a share of pixels (0..1) for the screen checks
  // Screen
  std::string picture;     ///< absolute path of the reference PNG
  // Post
  std::string program;     ///< absolute path of the teacher's program
  size_t postIndex = 0;    ///< its place among the assignment's post programs
  // Efficiency: tiers of (at most, points), the most demanding first.
  Measure measure = Statements;
  std::vector<std::pair<double, double>> tiers;
  // AnyOf, AllOf
  std::vector<Check> of;
};

/// The kind's name as the assignment file writes it ("solution-trail").
const char* kindName(Check::Kind kind);
/// The measure's name ("statements", "moves", "distance").
const char* measureName(Check::Measure measure);

struct Assignment {
  std::string path;                     ///< the assignment file
  std::string title;
  std::optional<std::string> solution;  ///< absolute path of the reference solution
  std::string world;                    ///< absolute path of the world program, or ""
  std::string roster;                   ///< absolute path of the roster (CSV), or ""
  /// Whether the assignment is about the robot, so that a program that never places or moves
  /// it earns nothing: set by `robot = true/false`, else inferred from the checks (and the
  /// solution, see Grader).
  std::optional<bool> aboutRobot;
  bool ports = false;                   ///< programs may open serial ports (rCommPort, a real robot)
  std::vector<uint64_t> seeds{1};       ///< each program runs once per seed
  uint64_t maxSteps = 10'000'000;       ///< statements per run (0: no limit)
  double timeout = 10;                  ///< seconds of real time per run
  uint64_t memoryMb = 512;              ///< memory per run
  bool maxStepsSet = false, timeoutSet = false;  ///< written in the file (for messages)
  std::string events;                   ///< absolute path of an events script, or ""
  std::string keys;
  std::vector<std::string> stdinLines;
  /// Files and folders every program gets a copy of beside it (`files = [...]` in [run]),
  /// absolute paths.
  std::vector<std::string> files;
  /// Programs may run other programs with Spawn (`spawn = true` in [run]); they stay in the
  /// kernel's confinement, as everything they start does.
  bool spawn = false;
  std::vector<Check> checks;

  bool needsSolution() const;
  /// A check compares final screens.
  bool needsScreen() const;
  /// The largest points total.
  double maxPoints() const;
  /// The post programs, in the order of their checks (Check::postIndex).
  std::vector<std::string> posts() const;
  /// The colours some avoid or touch check watches (0xRRGGBB), each once.
  std::vector<uint32_t> watchedColours() const;
  /// A check is about what the robot did (its path, trail, end, crashes or moves).
  bool robotChecks() const;
};

/// Reads and checks an assignment file. Relative paths in it (solution, events, pictures,
/// programs) are relative to the file's folder. nullopt with `error` ("FILE:LINE:COL: what is
/// wrong") when the file cannot be read or is not a valid assignment.
std::optional<Assignment> loadAssignment(const std::string& path, std::string& error);

/// Every check of the assignment, groups' members included, in file order.
std::vector<const Check*> allChecks(const Assignment& assignment);

}  // namespace rb::grade
