#pragma once
// One grade book from many machines (rb test --merge): the JSON reports of a class's shards
// (rb test --shard K/N --format json) read back and merged into the class's result, as one run
// over the whole class would have made it, for every report rb test writes.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grader.h"

namespace rb::grade {

/// The shape of rb test's JSON report that jsonReport() writes and readJsonReport() reads: 2
/// carries what merging needs (the report's "report_version"; reports without one are older).
constexpr int kJsonReportVersion = 2;

/// Standard base64 with padding (RFC 4648): how the JSON report carries a program's source.
std::string base64Encode(std::string_view bytes);
/// nullopt when `text` is not base64 (a character outside the alphabet, a bad length).
std::optional<std::string> base64Decode(std::string_view text);

/// A JSON report of rb test (--format json, report_version 2) read back into the result it was
/// written from: texts as the report shows them (shownText), a program's source byte for byte,
/// the grading's origin. nullopt with the reason in `error` for a text that is not such a report
/// (not JSON, another document, an older or newer report_version). `similarity`, when given, is
/// set to whether the report has a similarity list (which is not read back).
std::optional<ClassResult> readJsonReport(const std::string& text, std::string& error, bool* similarity = nullptr);

/// One shard's report as given to rb test --merge.
struct ShardReport {
  std::string file;    ///< as named on the command line
  ClassResult result;  ///< readJsonReport's
  bool similarity = false;  ///< the report had a similarity list (of its own programs only)
};

/// Reads and parses one shard's report file (readJsonReport). nullopt with rb's exit code in
/// `code` (66: the file cannot be read; 64: it is not such a report) and `error` naming the file.
std::optional<ShardReport> loadShard(const std::string& file, int& code, std::string& error);

/// What tells two assignment files apart, for the JSON report: FNV-1a (64 bits) of `bytes`, as
/// 16 hex digits.
std::string contentDigest(std::string_view bytes);

/// A picture, final screen or replay named in a shard's report that was not found.
struct MissingPicture {
  std::string report;    ///< the shard's report file
  std::string recorded;  ///< the path as the report recorded it
};

/// Finds each file a shard's report names (picture, screen, replay) on this machine and points
/// the program at it. With `picturesDir` (--merge-pictures): there, by its file name. Without:
/// the recorded path as it is (the shard ran here), then beside the report: the recorded path
/// below the report's folder, its last folder and file name there (an artifact that kept the
/// pictures folder beside the report), its file name there. A file not found is named in
/// `missing` and left out of the program's result.
void findShardPictures(ShardReport& shard, const std::string& picturesDir, std::vector<MissingPicture>& missing);

/// Copies every program's picture, screen and replay into `dir` (which exists), under its own
/// file name, as one run with --pictures DIR writes them, and points the programs there. Files
/// already there are left alone. Each file that cannot be copied is named in `errors`.
void copyPictures(ClassResult& result, const std::string& dir, std::vector<std::string>& errors);

/// The merge: the class's result from its shards' results, or why not.
struct MergeOutcome {
  ClassResult result;
  int code = 0;       ///< 0 merged; 64 reports that do not belong together; 66 a shard is missing
  std::string error;  ///< why not, naming the reports
};
/// Every shard 1..N of one grading (same rb, title, assignment and digest, paths, view) exactly
/// once, no program in two shards. The programs sorted by path as one run sorts them, the
/// roster's missing students once after them; the counts counted again; the warnings once each;
/// the kernel's confinement notes once each; the timestamp the earliest shard's, the seconds
/// from it to the end of the shard that ended last. Similarity is not merged (each shard's
/// compares its own programs only): findSimilar over the merged programs gives the class's.
MergeOutcome mergeShards(std::vector<ShardReport> shards);

/// --similarity over a merged class, as one run compares it: every graded program (not the
/// class's other files, not missing students), in order, each with its text as graded (a program
/// rb could not read is read from its path, as one run does); `ignore` as --similarity-ignore.
SimilarityReport classSimilarity(const ClassResult& result, const std::vector<std::string>& ignore);

}  // namespace rb::grade
