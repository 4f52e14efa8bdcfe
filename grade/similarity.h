#pragma once
// `rb test --similarity`: pairs of programs in a class whose code is much alike, for the teacher
// to look at side by side. A teacher's aid, never a verdict: students who solve one small task
// with one set of commands write much the same code, and a high score only says where to look.
//
// How it works (winnowing, as MOSS and Dolos do it: Schleimer, Wilkerson and Aiken, "Winnowing:
// local algorithms for document fingerprinting", SIGMOD 2003):
//
//  1. Each program is read (UTF-8 or Windows-1252, as rb reads programs) and split into tokens
//     by rb's own lexer (lang/lexer.h). The tokens are normalised so that cosmetic changes do
//     not matter:
//       - every name a program makes up (variable, array, label and sub names) is one token,
//         "a name": renaming changes nothing. A word is a name unless it is a keyword or a
//         built-in of rb's standard table (machine/builtins.h; compared without regard to case,
//         as RobotBASIC does) where the language lets that built-in stand: a command as the
//         first word of a statement (at the start of a line, after a label, `then` or `else`),
//         a function followed by '(', a constant anywhere (as a number, below). So a label,
//         the word after gosub, goto, sub and call, a word assigned to or used as an array,
//         and a function's name without '(' are names even when spelled like a built-in
//         (`length = 90` is a variable, though rb would reject it: such a program is still
//         compared);
//       - every number literal is one token, "a number", and so is every built-in constant
//         (GREEN is the number 2, DOWN is 1: changing a colour is changing a number); every
//         string literal is one token, "a string";
//       - keywords, operators, punctuation and built-in command and function names are kept as
//         they are (built-ins and keywords in any case count as the same);
//       - comments, blank lines, indentation, spaces and line breaks are left out.
//     Each normalised token remembers the line it came from.
//  2. Every k consecutive tokens (a k-gram) are hashed. In every window of `window` consecutive
//     k-gram hashes the smallest is selected (the rightmost one when several are smallest); each
//     selection is recorded once with its position: the program's fingerprints. Any run of
//     window + k - 1 tokens that two programs share gives both at least one common fingerprint,
//     and nothing shorter than k tokens can. A program with fewer k-grams than the window gets
//     its one smallest hash.
//  3. Fingerprints are compared as sets of hashes (a hash a program has twice counts once):
//       - the ignored files' code (a starting template every student got; MOSS calls it the
//         base file) is removed: every k-gram hash of every ignored file (all of them, not only
//         its fingerprints, so that template code is removed whatever a program puts around it)
//         is taken out of every program's fingerprints;
//       - fingerprints found in more than `commonShare` of the compared programs (half, by
//         default) are boilerplate every solution has and are taken out too, but only those in
//         at least `commonMinPrograms` programs, so that in a small class two copies are not
//         taken for boilerplate. This drops code many students share for a reason (the
//         assignment's set-up lines), and it also hides code copied by more than half a class;
//       - what is taken out counts neither in what two programs share nor in their sizes.
//     An inverted index from each hash to the programs that have it gives, for each program,
//     the fingerprints it shares with every other without comparing all pairs' sets.
//  4. For each pair: shareA = shared / A's fingerprints, shareB = shared / B's, and
//     score = max(shareA, shareB): the share of the program that is more fully found in the
//     other. A program copied and then padded with code of its own still scores high (its
//     source is wholly in it); the price is that a very short program inside a long one scores
//     high too, so both shares are reported and the ranking puts more shared fingerprints first
//     among equal scores.
//  5. For the pairs kept, the matching fingerprints are merged into blocks: matches in order in
//     both files, no more than window + k tokens apart, make one run (a run follows the match
//     that keeps its step most alike in both files, as a copy does); each run is widened to the
//     identical normalised tokens just around it (up to window + k tokens each way, which is
//     what winnowing may have left unselected at its ends) but never into the template's code.
//     Longest first, a run's tokens that correspond in both files make a block, less those a
//     longer block took: what is left is cut to its longest stretch, kept if it still holds k
//     tokens, so no token is in two blocks (at most 100 blocks a pair). A block's lines are
//     those of its first and last tokens, so a line may hold the end of one block and the
//     start of the next; its rows put the lines whose tokens correspond side by side. Code
//     shorter than window + k - 1 tokens between two changes may match nothing, and the
//     k-grams across the seams of moved code are lost: reordered parts keep their blocks, with
//     a lower score.
//
// Limits, so that no input can take unbounded time or memory: a file is read up to 4 MiB, a
// line up to 16 KiB (the rest of a longer line is left out), a program up to 500,000 tokens
// (a note says when any of these cut a file); a file with more than 256 characters the lexer
// cannot read is not RobotBASIC and is skipped, as are binary files, files that are not regular
// files (a folder, a pipe) and files too short to have one k-gram. Every skip is a note. The
// blocks of a pair come from reading its two files again: a file changed meanwhile gets no
// blocks and a note.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rb::grade {

struct SimilarityOptions {
  /// The text of a program as graded (rb test's copy, read before any run), or nullopt to read
  /// the file. Unset: every file is read. Called from several threads at once (see threads),
  /// and twice for each program compared (once a pass) and once more for a program of a pair
  /// reported: it must give the same text each time.
  std::function<std::optional<std::string>(const std::string& path)> source;
  /// Threads that read and compare the programs; 0: one for each processor. The report is the
  /// same with any number.
  size_t threads = 0;
  /// Tokens in a k-gram: the shortest run of code two programs must share to count at all
  /// (12 tokens are about two short statements). Values below 1 count as 1.
  size_t k = 12;
  /// k-grams in a window: a fingerprint is kept at least every `window` k-grams, so any shared
  /// run of window + k - 1 tokens is found (19 with the defaults). Values below 1 count as 1.
  size_t window = 8;
  /// The most pairs the report keeps (the best ranked); 0 keeps them all.
  size_t maxPairs = 50;
  /// A pair is reported when its score is at least this (0 to 1). Pairs with no fingerprint in
  /// common are never reported.
  double minScore = 0.3;
  /// A pair is reported only when it has at least this many fingerprints in common: one or two
  /// shared fingerprints (a line or two once boilerplate is gone) are no evidence of anything.
  size_t minShared = 3;
  /// Files whose code does not count (a template the students started from): see above.
  std::vector<std::string> ignore;
  /// Fingerprints in more than this share of the compared programs are boilerplate and do not
  /// count (1 or more: none is).
  double commonShare = 0.5;
  /// ... provided they are in at least this many programs.
  size_t commonMinPrograms = 5;
};

struct LineRange {
  uint32_t first = 0, last = 0;  ///< 1-based, inclusive
};

/// A run of matching code in both files.
struct SharedBlock {
  LineRange a, b;
  /// Normalised tokens in the run (the fewer of the two files' counts).
  size_t tokens = 0;
  /// The text of lines a.first..a.last of file a, and of b.first..b.last of file b (UTF-8,
  /// without line endings, tabs kept): at most 100 lines each, each cut at 240 bytes.
  std::vector<std::string> linesA, linesB;
  /// One row of the side-by-side view: a line of a and a line of b (0: none on that side).
  struct Row {
    uint32_t a = 0, b = 0;
  };
  /// The block's lines side by side (at most 100 rows): lines whose tokens match are on one row;
  /// the lines between them that match nothing (a comment, a blank line, code of one file only)
  /// are put next to each other as they come, and alone when one file has more of them.
  std::vector<Row> rows;
};

struct SimilarPair {
  std::string a, b;          ///< program paths as given; a is the one given first
  double shareA = 0;         ///< the fraction of a's fingerprints found in b
  double shareB = 0;         ///< the fraction of b's fingerprints found in a
  double score = 0;          ///< max(shareA, shareB)
  size_t shared = 0;         ///< fingerprints (distinct hashes) in common
  size_t fingerprintsA = 0;  ///< a's fingerprints that count (distinct, without template and boilerplate)
  size_t fingerprintsB = 0;  ///< b's
  std::vector<SharedBlock> blocks;  ///< longest first (then by line in a)
};

struct SimilarityReport {
  /// Best first: by score, then shared fingerprints (more first), then a's path, then b's.
  std::vector<SimilarPair> pairs;
  size_t programs = 0;  ///< programs compared
  size_t skipped = 0;   ///< programs not compared (each has a note); programs + skipped = given
  size_t matching = 0;  ///< pairs whose score reached minScore, before the maxPairs cut
  size_t common = 0;    ///< distinct fingerprints dropped as boilerplate
  double minScore = 0;  ///< the options' minScore, for the text
  /// What the teacher should know: skipped files and why, files cut, templates not read.
  std::vector<std::string> notes;
};

/// Reads and fingerprints every program (unreadable files and files too short to have a k-gram
/// are noted and skipped), compares every pair, keeps pairs with score >= minScore, ranked by
/// score (then shared, then names), at most maxPairs. Never throws for bad input: any file is
/// read, skipped or cut with a note.
SimilarityReport findSimilar(const std::vector<std::string>& programs, const SimilarityOptions& options = {});

/// Text for the terminal: a heading (two lines; one when no pair is found), then one block per
/// pair: its rank, the score as a percentage and both files, both shares, then at most 3 shared
/// blocks (the longest) with both files' lines side by side (SharedBlock::rows): line number
/// and text, each column 50 characters wide (longer lines cut, ending in "~"), the columns
/// separated by " | ", at most 24 rows a block. Then the notes, each "note: ...". Percentages
/// are rounded to the nearest, but only a whole is 100% and only nothing 0%. Tabs show as
/// spaces; text that is not UTF-8 is read as Latin-1.
std::string similarityText(const SimilarityReport& report);

/// The pairs as a JSON array, for rb test's JSON report: one object per pair, best first:
///   {"a": path, "b": path, "score": 0.93, "share_a": 0.93, "share_b": 0.88, "shared": 41,
///    "fingerprints_a": 44, "fingerprints_b": 47,
///    "blocks": [{"a": [first, last], "b": [first, last], "tokens": 80,
///                "lines_a": ["text", ...], "lines_b": ["text", ...],
///                "rows": [[line of a, line of b], [3, null], ...]}, ...]}
/// (a row's null: no line on that side; see SharedBlock::rows).
/// Fractions are rounded to 4 decimals; all text is UTF-8. Ends with a line end.
std::string similarityJson(const SimilarityReport& report);

/// For the tests: the steps findSimilar takes, one at a time.
namespace detail {
/// The normalised token codes of a program's text: by rb's lexer (`quick` false: nullopt when
/// the lexer finds it is not RobotBASIC), or by the quick scan that reads most programs
/// (`quick` true: nullopt when it leaves the text to the lexer). Where both give codes, they
/// are the same.
std::optional<std::vector<uint32_t>> normalisedCodes(const std::string& text, bool quick);
/// The positions winnowing selects among `hashes` with a window of w (see above).
std::vector<uint32_t> winnowed(const std::vector<uint64_t>& hashes, size_t w);
/// A program's distinct fingerprints as findSimilar counts them (k and window as in the
/// options, no ignored files), from its text.
std::vector<uint64_t> fingerprintsOf(const std::string& text, size_t k, size_t w);
}  // namespace detail

}  // namespace rb::grade
