#include "merge.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "png_writer.h"

namespace rb::grade {

using record::RunRecord;

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

/// The largest picture or replay merging copies: a replay is at most 64 MB (rb test's limit on
/// what a run writes).
constexpr uintmax_t kCopyLimit = 64ull << 20;
/// The largest report merging reads: each program's output and error output are at most 64 KiB
/// in it, so 4 GiB is tens of thousands of programs printing all they may.
constexpr uintmax_t kReportLimit = 4ull << 30;

bool isVerdict(const std::string& v) {
  return v == "pass" || v == "fail" || v == "skip" || v == "error" || v == "missing";
}

/// "2026-11-28T09:53:08" (rb test's timestamps, UTC) as seconds since the epoch.
std::optional<double> epochOf(const std::string& iso) {
  std::tm tm{};
  int used = 0;
  if (std::sscanf(iso.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d%n", &tm.tm_year, &tm.tm_mon, &tm.tm_mday, &tm.tm_hour,
                  &tm.tm_min, &tm.tm_sec, &used) != 6 ||
      static_cast<size_t>(used) != iso.size())
    return std::nullopt;
  tm.tm_year -= 1900;
  tm.tm_mon -= 1;
  return static_cast<double>(timegm(&tm));
}

CheckResult checkOf(const json& j) {
  CheckResult c;
  c.name = j.at("name").get<std::string>();
  c.passed = j.at("passed").get<bool>();
  c.checked = j.value("checked", true);
  c.message = j.value("message", "");
  c.points = j.value("points", 1.0);
  c.earned = j.value("earned", 0.0);
  c.note = j.value("note", "");
  c.hint = j.value("hint", "");
  c.hidden = j.value("hidden", false);
  c.required = j.value("required", false);
  c.feedback = j.value("feedback", std::vector<std::string>{});
  return c;
}

/// One program of the report, or throws std::runtime_error saying what is wrong with it.
ProgramResult programOf(const json& j) {
  ProgramResult p;
  p.program = j.at("program").get<std::string>();
  p.verdict = j.at("result").get<std::string>();
  if (!isVerdict(p.verdict)) throw std::runtime_error(p.program + ": the result '" + p.verdict + "' is none of rb's");
  p.reason = j.value("reason", "");
  p.steps = j.value("steps", uint64_t{0});
  p.seconds = j.value("seconds", 0.0);
  p.points = j.value("points", 0.0);
  p.maxPoints = j.value("max_points", 0.0);
  p.student = j.value("student", "");
  p.gate = j.value("gate", "");
  p.notes = j.value("notes", std::vector<std::string>{});
  p.name = j.value("name", "");
  p.isProgram = !j.value("not_a_program", false);
  if (j.contains("source_base64")) {
    std::optional<std::string> source = base64Decode(j.at("source_base64").get<std::string>());
    if (!source) throw std::runtime_error(p.program + ": its source_base64 is not base64");
    p.source = std::move(*source);
    p.sourceRead = true;
  }
  p.picture = j.value("picture", "");
  p.pictureCaption = j.value("picture_caption", "");
  p.screen = j.value("screen", "");
  p.replay = j.value("replay", "");
  p.output = j.value("output", "");
  p.errors = j.value("errors", "");
  if (j.contains("checks"))
    for (const json& c : j.at("checks")) p.checks.push_back(checkOf(c));
  if (j.contains("inputs")) {
    size_t after = 0;
    for (const json& m : j.at("inputs")) {
      RunRecord::InputMark mark{m.at("start").get<size_t>(), m.at("prompt_end").get<size_t>(), m.at("end").get<size_t>()};
      // In order, each within the output: the transcripts walk the output once.
      if (mark.start < after || mark.promptEnd < mark.start || mark.end < mark.promptEnd || mark.end > p.output.size())
        throw std::runtime_error(p.program + ": an input mark (" + std::to_string(mark.start) + ", " +
                                 std::to_string(mark.promptEnd) + ", " + std::to_string(mark.end) +
                                 ") lies outside its output or before the mark ahead of it");
      after = mark.end;
      p.inputs.push_back(mark);
    }
  }
  if (j.contains("marks"))
    for (const json& m : j.at("marks")) p.marks.push_back({m.at("line").get<uint32_t>(), m.value("message", "")});
  return p;
}

bool readBytes(const std::string& path, uintmax_t cap, std::string& bytes, std::string& why) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    why = fs::exists(path, ec) ? "not a regular file" : "no such file";
    return false;
  }
  uintmax_t size = fs::file_size(path, ec);
  if (ec || size > cap) {
    why = ec ? ec.message() : "larger than " + std::to_string(cap >> 20) + " MB";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  bytes.assign(static_cast<size_t>(size), '\0');
  if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(size))) {
    why = "cannot read it";
    return false;
  }
  return true;
}

bool isFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

std::string found(const std::string& recorded, const std::string& reportFile, const std::string& picturesDir) {
  if (recorded.empty()) return "";
  fs::path rec(recorded);
  if (!picturesDir.empty()) {
    fs::path there = fs::path(picturesDir) / rec.filename();
    return isFile(there) ? there.string() : "";
  }
  if (isFile(rec)) return recorded;
  fs::path beside = fs::path(reportFile).parent_path();
  std::vector<fs::path> candidates;
  if (rec.is_relative()) candidates.push_back(beside / rec);
  if (rec.has_parent_path() && !rec.parent_path().filename().empty())
    candidates.push_back(beside / rec.parent_path().filename() / rec.filename());
  candidates.push_back(beside / rec.filename());
  for (const fs::path& c : candidates)
    if (isFile(c)) return c.string();
  return "";
}

std::string shardName(const ShardReport& s) {
  return s.file + " (shard " + std::to_string(s.result.origin.shard) + " of " + std::to_string(s.result.origin.shards) + ")";
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& i : items) out += (out.empty() ? "" : " ") + i;
  return out;
}

}  // namespace

std::string base64Encode(std::string_view bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    uint32_t v = static_cast<uint32_t>(static_cast<unsigned char>(bytes[i])) << 16 |
                 static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                 static_cast<unsigned char>(bytes[i + 2]);
    for (int shift : {18, 12, 6, 0}) out += kAlphabet[(v >> shift) & 63];
  }
  if (i < bytes.size()) {
    uint32_t v = static_cast<uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::optional<std::string> base64Decode(std::string_view text) {
  if (text.size() % 4 != 0) return std::nullopt;
  std::string out;
  out.reserve(text.size() / 4 * 3);
  for (size_t i = 0; i < text.size(); i += 4) {
    uint32_t v = 0;
    int pad = 0;
    for (size_t k = 0; k < 4; ++k) {
      char c = text[i + k];
      uint32_t d = 0;
      if (c == '=') {
        // Padding only at the very end, at most two, and nothing but padding after it.
        if (i + 4 != text.size() || k < 2) return std::nullopt;
        ++pad;
      } else {
        if (pad) return std::nullopt;
        const char* at = std::char_traits<char>::find(kAlphabet, 64, c);
        if (!at) return std::nullopt;
        d = static_cast<uint32_t>(at - kAlphabet);
      }
      v = v << 6 | d;
    }
    out += static_cast<char>((v >> 16) & 255);
    if (pad < 2) out += static_cast<char>((v >> 8) & 255);
    if (pad < 1) out += static_cast<char>(v & 255);
  }
  return out;
}

std::optional<ClassResult> readJsonReport(const std::string& text, std::string& error, bool* similarity) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    error = "not JSON: " + std::string(e.what());
    return std::nullopt;
  }
  if (!doc.is_object() || !doc.contains("programs") || !doc.contains("summary")) {
    error = "not a report of rb test --format json (it has no programs and summary)";
    return std::nullopt;
  }
  if (!doc.contains("report_version")) {
    error = "written by an older rb test, whose JSON report leaves out what merging needs (each program's source, "
            "name, screen and marked lines, the shard): grade it again with this rb";
    return std::nullopt;
  }
  ClassResult r;
  try {
    int version = doc.at("report_version").get<int>();
    if (version != kJsonReportVersion) {
      error = "report_version " + std::to_string(version) + ", which this rb does not read (it reads " +
              std::to_string(kJsonReportVersion) + "): merge with the rb that graded";
      return std::nullopt;
    }
    r.title = doc.value("title", "rb test");
    r.timestamp = doc.value("timestamp", "");
    r.studentView = doc.value("student_view", false);
    r.origin.rbVersion = doc.value("rb_version", "");
    r.origin.paths = doc.value("paths", std::vector<std::string>{});
    if (doc.contains("shard")) {
      r.origin.shard = doc.at("shard").at("index").get<int>();
      r.origin.shards = doc.at("shard").at("of").get<int>();
    }
    if (r.origin.shards < 1 || r.origin.shard < 1 || r.origin.shard > r.origin.shards) {
      error = "its shard " + std::to_string(r.origin.shard) + " of " + std::to_string(r.origin.shards) +
              " is not one (1 <= K <= N)";
      return std::nullopt;
    }
    if (doc.contains("assignment")) {
      const json& a = doc.at("assignment");
      r.assignment = true;
      r.maxPoints = a.value("max_points", 0.0);
      r.origin.assignmentFile = a.value("file", "");
      r.origin.assignmentDigest = a.value("digest", "");
    }
    r.warnings = doc.value("warnings", std::vector<std::string>{});
    r.confinement = doc.value("confinement", "");
    for (const json& p : doc.at("programs")) r.programs.push_back(programOf(p));
    const json& s = doc.at("summary");
    r.seconds = s.value("seconds", 0.0);
    for (const ProgramResult& p : r.programs) {
      if (p.verdict == "pass") ++r.passed;
      else if (p.verdict == "skip") ++r.skipped;
      else if (p.verdict == "error") ++r.errors;
      else if (p.verdict == "missing") ++r.missing;
      else ++r.failed;
    }
    size_t graded = r.programs.size() - r.missing;
    if (s.value("programs", graded) != graded || s.value("passed", r.passed) != r.passed ||
        s.value("failed", r.failed) != r.failed || s.value("errors", r.errors) != r.errors ||
        s.value("skipped", r.skipped) != r.skipped || s.value("missing", r.missing) != r.missing) {
      error = "its summary does not count its programs (" + std::to_string(graded) + " programs: " +
              std::to_string(r.passed) + " passed, " + std::to_string(r.failed) + " failed, " +
              std::to_string(r.errors) + " not graded, " + std::to_string(r.skipped) + " skipped, " +
              std::to_string(r.missing) + " missing): was it edited?";
      return std::nullopt;
    }
    if (similarity) *similarity = doc.contains("similarity");
  } catch (const std::exception& e) {
    error = "not a report rb test wrote: " + std::string(e.what());
    return std::nullopt;
  }
  return r;
}

std::optional<ShardReport> loadShard(const std::string& file, int& code, std::string& error) {
  ShardReport shard;
  shard.file = file;
  std::string text, why;
  if (!readBytes(file, kReportLimit, text, why)) {
    code = 66;
    error = "cannot read the report " + file + ": " + why;
    return std::nullopt;
  }
  std::optional<ClassResult> r = readJsonReport(text, why, &shard.similarity);
  if (!r) {
    code = 64;
    error = file + ": " + why;
    return std::nullopt;
  }
  shard.result = std::move(*r);
  return shard;
}

std::string contentDigest(std::string_view bytes) {
  uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  char text[24];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

void findShardPictures(ShardReport& shard, const std::string& picturesDir, std::vector<MissingPicture>& missing) {
  for (ProgramResult& p : shard.result.programs)
    for (std::string* file : {&p.picture, &p.screen, &p.replay}) {
      if (file->empty()) continue;
      std::string at = found(*file, shard.file, picturesDir);
      if (at.empty()) missing.push_back({shard.file, *file});
      *file = at;
    }
}

void copyPictures(ClassResult& result, const std::string& dir, std::vector<std::string>& errors) {
  for (ProgramResult& p : result.programs)
    for (std::string* file : {&p.picture, &p.screen, &p.replay}) {
      if (file->empty()) continue;
      fs::path to = fs::path(dir) / fs::path(*file).filename();
      std::error_code ec;
      if (fs::equivalent(*file, to, ec)) {
        *file = to.string();
        continue;
      }
      std::string bytes, why;
      if (!readBytes(*file, kCopyLimit, bytes, why)) {
        errors.push_back("cannot copy '" + *file + "' to '" + to.string() + "': " + why);
        continue;
      }
      if (!render::writeFileBytes(to.string(), bytes.data(), bytes.size(), why)) {
        errors.push_back(why);
        continue;
      }
      *file = to.string();
    }
}

MergeOutcome mergeShards(std::vector<ShardReport> shards) {
  MergeOutcome out;
  auto refuse = [&](int code, std::string why) {
    out.code = code;
    out.error = std::move(why);
    return out;
  };
  if (shards.empty()) return refuse(64, "no reports to merge");
  std::stable_sort(shards.begin(), shards.end(), [](const ShardReport& a, const ShardReport& b) {
    return a.result.origin.shard < b.result.origin.shard;
  });
  // One grading: everything that tells gradings apart is the same in every report.
  const ShardReport& first = shards.front();
  const ClassResult& f = first.result;
  for (const ShardReport& s : shards) {
    const ClassResult& r = s.result;
    std::string a = shardName(first), b = shardName(s);
    if (r.origin.rbVersion != f.origin.rbVersion)
      return refuse(64, a + " was graded by rb " + f.origin.rbVersion + ", " + b + " by rb " + r.origin.rbVersion +
                            ": grade every shard with the same rb");
    if (r.assignment != f.assignment || r.origin.assignmentDigest != f.origin.assignmentDigest ||
        (r.origin.assignmentDigest.empty() && r.origin.assignmentFile != f.origin.assignmentFile)) {
      auto what = [](const ClassResult& c) {
        return c.assignment ? "the assignment " + c.origin.assignmentFile + " (digest " + c.origin.assignmentDigest + ")"
                            : std::string("the programs' comments");
      };
      return refuse(64, a + " was graded against " + what(f) + ", " + b + " against " + what(r) +
                            ": the shards of a class are graded against one assignment");
    }
    if (r.title != f.title)
      return refuse(64, a + " is of '" + f.title + "', " + b + " of '" + r.title + "': not one assignment");
    if (r.origin.paths != f.origin.paths)
      return refuse(64, a + " graded " + joined(f.origin.paths) + ", " + b + " graded " + joined(r.origin.paths) +
                            ": the shards of a class grade the same files and folders");
    if (r.studentView != f.studentView)
      return refuse(64, (f.studentView ? a : b) + " is a report for students (--student), " + (f.studentView ? b : a) +
                            " is not: grade every shard alike");
    if (r.origin.shards != f.origin.shards)
      return refuse(64, a + " and " + b + " split the class differently: every shard is graded with --shard K/N, one N");
  }
  // Every shard once.
  int n = f.origin.shards;
  std::vector<const ShardReport*> byIndex(static_cast<size_t>(n) + 1, nullptr);
  for (const ShardReport& s : shards) {
    if (s.result.origin.shard < 1 || s.result.origin.shard > n)
      return refuse(64, s.file + " says it is shard " + std::to_string(s.result.origin.shard) + " of " + std::to_string(n));
    const ShardReport*& at = byIndex[static_cast<size_t>(s.result.origin.shard)];
    if (at) return refuse(64, at->file + " and " + s.file + " are both shard " + std::to_string(s.result.origin.shard) + " of " + std::to_string(n));
    at = &s;
  }
  std::vector<std::string> absent;
  for (int k = 1; k <= n; ++k)
    if (!byIndex[static_cast<size_t>(k)]) absent.push_back(std::to_string(k));
  if (!absent.empty()) {
    std::string list;
    for (size_t i = 0; i < absent.size(); ++i)
      list += (i == 0 ? "" : i + 1 == absent.size() ? " and " : ", ") + absent[i];
    return refuse(66, std::string(absent.size() == 1 ? "shard " : "shards ") + list + " of " + std::to_string(n) +
                          (absent.size() == 1 ? " is" : " are") + " missing: merge the reports of every shard");
  }
  // No program in two shards.
  std::map<std::string, const ShardReport*> owner;
  for (const ShardReport& s : shards)
    for (const ProgramResult& p : s.result.programs) {
      if (p.verdict == "missing") continue;
      auto [it, fresh] = owner.emplace(p.program, &s);
      if (!fresh)
        return refuse(64, p.program + " is in both " + shardName(*it->second) + " and " + shardName(s) +
                              ": the shards overlap (was the class folder changed between them?)");
    }

  ClassResult& r = out.result;
  r.title = f.title;
  r.assignment = f.assignment;
  r.studentView = f.studentView;
  r.maxPoints = f.maxPoints;
  r.origin = f.origin;
  r.origin.shard = r.origin.shards = 1;
  // The programs as one run orders them (grader.cpp): by path, the missing students after them,
  // each listed once (rb test lists them in shard 1).
  std::set<std::pair<std::string, std::string>> missing;
  std::vector<ProgramResult> absentStudents;
  for (ShardReport& s : shards)
    for (ProgramResult& p : s.result.programs) {
      if (p.verdict != "missing") r.programs.push_back(std::move(p));
      else if (missing.insert({p.program, p.student}).second) absentStudents.push_back(std::move(p));
    }
  std::stable_sort(r.programs.begin(), r.programs.end(),
                   [](const ProgramResult& a, const ProgramResult& b) { return a.program < b.program; });
  for (ProgramResult& p : absentStudents) r.programs.push_back(std::move(p));
  for (const ProgramResult& p : r.programs) {
    if (p.verdict == "pass") ++r.passed;
    else if (p.verdict == "skip") ++r.skipped;
    else if (p.verdict == "error") ++r.errors;
    else if (p.verdict == "missing") ++r.missing;
    else ++r.failed;
  }
  // What every shard says once (each ran the solution itself), in shard order.
  for (const ShardReport& s : shards)
    for (const std::string& w : s.result.warnings)
      if (std::find(r.warnings.begin(), r.warnings.end(), w) == r.warnings.end()) r.warnings.push_back(w);
  std::vector<std::string> confinements;
  for (const ShardReport& s : shards)
    if (!s.result.confinement.empty() &&
        std::find(confinements.begin(), confinements.end(), s.result.confinement) == confinements.end())
      confinements.push_back(s.result.confinement);
  for (const std::string& c : confinements) r.confinement += (r.confinement.empty() ? "" : "; ") + c;
  // When: from the first shard's start to the last one's end (timestamps are to the second).
  r.timestamp = f.timestamp;
  for (const ShardReport& s : shards)
    if (!s.result.timestamp.empty() && (r.timestamp.empty() || s.result.timestamp < r.timestamp)) r.timestamp = s.result.timestamp;
  std::optional<double> start = epochOf(r.timestamp);
  for (const ShardReport& s : shards) {
    std::optional<double> at = epochOf(s.result.timestamp);
    double end = s.result.seconds + (start && at ? *at - *start : 0);
    r.seconds = std::max(r.seconds, end);
  }
  return out;
}

SimilarityReport classSimilarity(const ClassResult& result, const std::vector<std::string>& ignore) {
  std::vector<std::string> programs;
  std::map<std::string, const ProgramResult*> by;
  for (const ProgramResult& p : result.programs) {
    if (p.verdict == "missing" || !p.isProgram) continue;
    programs.push_back(p.program);
    by[p.program] = &p;
  }
  SimilarityOptions options;
  options.ignore = ignore;
  options.source = [&by](const std::string& path) -> std::optional<std::string> {
    auto it = by.find(path);
    if (it == by.end() || !it->second->sourceRead) return std::nullopt;
    return it->second->source;
  };
  return findSimilar(programs, options);
}

}  // namespace rb::grade
