#pragma once
// rb trace's streams: what the robot did, event by event (and with --lines every statement),
// what the program printed, and how the run ended, as text, JSON Lines or CSV (man rb-trace has
// the fields). A TraceWriter watches one run: it is the run's robot observer, and the host
// calls line() before each statement and output() for what the program prints.

#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "base/diagnostic.h"
#include "base/source.h"
#include "machine/interpreter.h"
#include "machine/machine.h"

namespace rb::record {

struct TraceSettings {
  std::string format = "text";  ///< text, jsonl or csv
  bool sensors = false;         ///< also every sensor reading
  bool lines = false;           ///< also every statement
};

/// How the run ended, for the end record: it ran (`result`), or its load errors rejected it
/// (`loadErrors`), or it did not run at all (`notRun` says why).
struct TraceEnd {
  int exit = 0;                              ///< rb's exit code for the program
  const RunResult* result = nullptr;
  bool stepLimitIsError = false;             ///< --max-steps was asked for: reaching it is an error
  uint64_t steps = 0;                        ///< statements run (with result)
  const DiagnosticList* loadErrors = nullptr;
  std::string notRun;
};

struct TraceRecord;

class TraceWriter : public RobotObserver {
 public:
  /// `program` is set when several programs share one stream: each record names it.
  /// `csvHeader`: write CSV's header line (the first program of a stream). `sources` and
  /// `machine` give the program's files and the machine once they exist (nullptr before).
  TraceWriter(TraceSettings settings, std::FILE* out, std::string program, bool csvHeader,
              std::function<const SourceSet*()> sources, std::function<const Machine*()> machine);

  void robotEvent(const RobotEvent& e) override;
  /// Before each statement: remembers where the program is (for output) and lists it with
  /// `lines`.
  void line(SourceLoc loc);
  void output(std::string_view text);
  /// The end record: how the run ended, after how many steps, where the robot is.
  void end(const TraceEnd& e);
  /// Statements started so far.
  uint64_t statements() const { return statements_; }

 private:
  std::string fileName(SourceLoc loc) const;
  void write(const TraceRecord& r);
  void writeJson(const TraceRecord& r);
  void writeCsv(const TraceRecord& r);
  void writeText(const TraceRecord& r);

  TraceSettings opts_;
  std::FILE* out_;
  std::string program_;
  std::function<const SourceSet*()> sources_;
  std::function<const Machine*()> machine_;
  uint64_t seq_ = 0;
  SourceLoc last_;           ///< the statement running now
  uint64_t statements_ = 0;  ///< statements started so far
};

}  // namespace rb::record
