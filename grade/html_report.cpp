#include "html_report.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>

#include "png_writer.h"
#include "report.h"
#include "text.h"

namespace rb::grade {

namespace fs = std::filesystem;

namespace {

/// The most of a program's source a page shows.
constexpr size_t kSourceCap = 1 << 20;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string verdictText(const std::string& verdict) {
  if (verdict == "pass") return "passed";
  if (verdict == "fail") return "failed";
  if (verdict == "error") return "not graded";
  if (verdict == "skip") return "skipped";
  if (verdict == "missing") return "no submission";
  return verdict;
}

/// A verdict as a symbol and a word, never a colour alone: the symbol is for the eye (screen
/// readers skip it), the word for everyone.
std::string verdictBadge(const std::string& verdict) {
  const char* symbol = verdict == "pass" ? "&#10003;" : verdict == "skip" ? "&#8211;" : "&#10007;";
  return "<span class=\"verdict " + htmlEscape(verdict) + "\"><span aria-hidden=\"true\">" + symbol + " </span>" +
         verdictText(verdict) + "</span>";
}

/// A check's mark: a symbol and a word (passed, failed, not checked).
std::string checkMark(const CheckResult& c) {
  const char* mark = !c.checked ? "&#8211;" : c.passed ? "&#10003;" : "&#10007;";
  const char* word = !c.checked ? "not checked" : c.passed ? "passed" : "failed";
  return std::string("<span class=\"mark\" aria-hidden=\"true\">") + mark + "</span> <span class=\"word\">" + word +
         "</span> ";
}

std::string displayName(const ProgramResult& p) {
  return p.student.empty() ? p.program : p.student;
}

/// The page's head: the title, the style, and a Content Security Policy that runs no script
/// but the page's own (its nonce), loads nothing from the network and images and frames only
/// from files beside it.
std::string head(const std::string& title, const std::string& nonce, const char* style) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src 'self' file: data:; "
         "frame-src 'self' file:; style-src 'unsafe-inline'; script-src 'nonce-" + nonce +
         "'; base-uri 'none'; form-action 'none'\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<meta name=\"generator\" content=\"rb test --html\">\n";
  out += "<title>" + htmlEscape(title) + "</title>\n<style>\n";
  out += style;
  out += "</style>\n</head>\n";
  return out;
}

const char* kCommonStyle = R"(
:root { color-scheme: light; --pass: #1b7f3b; --fail: #b3261e; --other: #6b6b6b; --focus: #0b57d0; }
body { font: 15px/1.4 system-ui, sans-serif; margin: 0; background: #f4f4f2; color: #1d1d1d; }
header { background: #20313f; color: #fff; padding: 12px 20px; }
header h1 { margin: 0 0 4px; font-size: 22px; }
header a { color: #cfe3ff; }
.verdict { font-weight: 600; padding: 1px 8px; border-radius: 10px; color: #fff; background: var(--other); }
.verdict.pass { background: var(--pass); }
.verdict.fail, .verdict.error, .verdict.missing { background: var(--fail); }
ul.checks { list-style: none; padding: 0; margin: 6px 0 0; font-size: 13px; }
ul.checks li { display: flex; gap: 6px; }
ul.checks li .pts { margin-left: auto; color: #555; white-space: nowrap; }
.mark { display: inline-block; width: 1.1em; text-align: center; font-weight: 700; }
.word { font-size: 12px; }
li.pass .mark, tr.pass .mark, tr.pass .word { color: var(--pass); }
li.fail .mark, tr.fail .mark, tr.fail .word { color: var(--fail); }
li.unchecked .mark, tr.unchecked .mark { color: var(--other); }
:focus-visible { outline: 3px solid var(--focus); outline-offset: 2px; }
header :focus-visible { outline-color: #ffd33d; }
)";

const char* kClassStyle = R"(
#controls { display: flex; flex-wrap: wrap; gap: 10px 18px; align-items: center; padding: 10px 20px;
            background: #e6e9ec; border-bottom: 1px solid #cdd2d6; position: sticky; top: 0; z-index: 1; }
#controls input[type=number] { width: 5em; }
@media (max-height: 500px) { #controls { position: static; } }
#cards { display: grid; grid-template-columns: repeat(auto-fill, minmax(230px, 1fr)); gap: 14px; padding: 16px 20px; }
.card { background: #fff; border: 1px solid #d4d4d0; border-radius: 6px; padding: 10px; overflow-wrap: anywhere;
        content-visibility: auto; contain-intrinsic-size: auto 560px; }
.card[hidden] { display: none; }
.card.fail, .card.error, .card.missing { border-top: 4px solid var(--fail); }
.card.pass { border-top: 4px solid var(--pass); }
.card a.open { color: inherit; text-decoration: none; display: block; }
.card a.open:hover h2 { text-decoration: underline; }
.card img, .card .noimage { width: 100%; aspect-ratio: 4 / 3; height: auto; display: block; background: #fafafa;
                            border: 1px solid #e2e2e2; }
.card .noimage { display: flex; align-items: center; justify-content: center; color: #595959; font-size: 13px; }
.card h2 { font-size: 16px; margin: 8px 0 0; }
.card .file { color: #555; font-size: 12px; margin: 0; }
.card .result { margin: 6px 0 0; display: flex; gap: 8px; align-items: center; }
.card .points { font-weight: 600; }
.card .reason { font-size: 13px; color: #444; margin: 6px 0 0; }
.warnings { margin: 10px 20px 0; padding: 8px 12px; background: #fff4d6; border: 1px solid #e0c36b; }
)";

const char* kProgramStyle = R"(
main { padding: 10px 20px 40px; max-width: 1200px; }
section { margin-top: 18px; }
h2 { font-size: 18px; margin: 0 0 8px; }
table.checks { border-collapse: collapse; background: #fff; }
table.checks td, table.checks th { border: 1px solid #ddd; padding: 4px 8px; vertical-align: top; text-align: left; }
table.checks .hint { color: #555; font-style: italic; }
table.checks .feedback { white-space: pre-wrap; font-family: ui-monospace, monospace; font-size: 13px; }
figure { display: inline-block; margin: 0 16px 16px 0; vertical-align: top; max-width: calc(50% - 16px); }
figure img { max-width: 100%; border: 1px solid #ccc; background: #fff; }
figcaption { font-size: 13px; color: #444; }
iframe.replay { width: 100%; height: 820px; max-height: 90vh; border: 1px solid #ccc; background: #fff; }
pre, .source { background: #fff; border: 1px solid #ddd; padding: 8px; overflow-x: auto; font: 13px/1.45 ui-monospace, monospace;
               white-space: pre; tab-size: 4; margin: 0; }
.source .l { display: block; }
.source .n { display: inline-block; width: 4em; color: #6b6b6b; text-align: right; margin-right: 1em; user-select: none; }
.source .l.bad { background: #fde3e1; }
.source .l.bad .n { color: var(--fail); font-weight: 700; }
.source .msg { display: block; color: var(--fail); padding-left: 5em; white-space: pre-wrap; font-style: italic; }
.notes { background: #fff4d6; border: 1px solid #e0c36b; padding: 6px 10px; }
)";

/// The class page's script: filters (name, points, result, a failed check) and sorting. It
/// reads only the cards' data attributes and sets `hidden` and the order.
const char* kClassScript = R"(
(() => {
  const $ = (id) => document.getElementById(id);
  const box = $('cards');
  const cards = Array.from(box.querySelectorAll('.card'));
  const rank = { fail: 0, error: 1, missing: 2, skip: 3, pass: 4 };
  const byName = (a, b) => a.dataset.name.localeCompare(b.dataset.name) || (a.dataset.index - b.dataset.index);
  const order = {
    'name': byName,
    'points-desc': (a, b) => (b.dataset.points - a.dataset.points) || byName(a, b),
    'points-asc': (a, b) => (a.dataset.points - b.dataset.points) || byName(a, b),
    'result': (a, b) => (rank[a.dataset.verdict] - rank[b.dataset.verdict]) || byName(a, b),
    'file': (a, b) => (a.dataset.index - b.dataset.index),
  };
  function apply() {
    const name = $('f-name').value.trim().toLocaleLowerCase();
    const min = parseFloat($('f-min').value), max = parseFloat($('f-max').value);
    const check = $('f-check').value, verdict = $('f-verdict').value;
    let shown = 0;
    for (const c of cards) {
      const d = c.dataset;
      const ok = (!name || d.name.toLocaleLowerCase().includes(name)) &&
                 (!verdict || d.verdict === verdict) &&
                 (!check || d.failed.split('\n').includes(check)) &&
                 (isNaN(min) || Number(d.points) >= min) && (isNaN(max) || Number(d.points) <= max);
      c.hidden = !ok;
      if (ok) shown++;
    }
    $('shown').textContent = shown + ' of ' + cards.length + ' shown';
    const sorted = cards.slice().sort(order[$('sort').value] || order.file);
    const frag = document.createDocumentFragment();
    for (const c of sorted) frag.appendChild(c);
    box.appendChild(frag);
  }
  for (const id of ['f-name', 'f-min', 'f-max', 'f-check', 'f-verdict', 'sort']) {
    $(id).addEventListener('input', apply);
    $(id).addEventListener('change', apply);
  }
  // A page reopened with the browser's back button keeps its controls' values: apply them (a
  // fresh page shows every card in file order as written, without touching them).
  const defaults = ['f-name', 'f-min', 'f-max', 'f-check', 'f-verdict'].every(id => $(id).value === '') &&
                   $('sort').value === 'file';
  if (defaults) $('shown').textContent = cards.length + ' of ' + cards.length + ' shown';
  else apply();
})();
)";

std::string nonceText() {
  std::random_device random;
  std::string out;
  const char* hex = "0123456789abcdef";
  for (int i = 0; i < 8; ++i) {
    unsigned v = random();
    for (int j = 0; j < 4; ++j) {
      out += hex[v & 15];
      v >>= 4;
    }
  }
  return out;
}

/// The picture or replay `file` as an element of a page in `pageDir`: an image, or for an HTML
/// replay a frame with the player and a link to open it on its own.
std::string imageTag(const std::string& file, const std::string& pageDir, const std::string& alt,
                     const std::string& extra) {
  return "<img src=\"" + htmlEscape(relativeUrl(file, pageDir)) + "\" alt=\"" + htmlEscape(alt) + "\"" + extra + ">";
}

std::string card(const ClassResult& r, size_t i, const std::string& page, const std::string& dir) {
  const ProgramResult& p = r.programs[i];
  std::string failedChecks;
  for (const CheckResult& raw : p.checks) {
    CheckResult c = shownCheck(raw, r.studentView);
    if (c.passed || !c.checked) continue;
    if (!failedChecks.empty()) failedChecks += "\n";
    failedChecks += c.name;
  }
  std::string name = displayName(p);
  std::string out = "<article class=\"card " + htmlEscape(p.verdict) + "\" data-index=\"" + std::to_string(i) +
                    "\" data-name=\"" + htmlEscape(p.student.empty() ? p.program : p.student + " " + p.program) +
                    "\" data-points=\"" + number(p.points) + "\" data-verdict=\"" + htmlEscape(p.verdict) +
                    "\" data-failed=\"" + htmlEscape(failedChecks) + "\">\n";
  out += page.empty() ? "<div class=\"open\">" : "<a class=\"open\" href=\"" + htmlEscape(page) + "\">";
  std::string screen = !p.screen.empty() ? p.screen : p.picture;
  if (!screen.empty())
    out += imageTag(screen, dir, "the final screen of " + name, " loading=\"lazy\" width=\"400\" height=\"300\"");
  else
    out += "<div class=\"noimage\">no picture</div>";
  out += "<h2>" + htmlEscape(name) + "</h2>";
  if (!p.student.empty()) out += "<p class=\"file\">" + htmlEscape(p.program) + "</p>";
  out += page.empty() ? "</div>\n" : "</a>\n";
  out += "<p class=\"result\">" + verdictBadge(p.verdict);
  if (r.assignment) out += "<span class=\"points\">" + number(p.points) + " / " + number(p.maxPoints) + "</span>";
  out += "</p>\n";
  std::string reason = shownReason(p, r.studentView);
  if (p.verdict != "pass" && !reason.empty())
    out += "<p class=\"reason\">" + htmlEscape(reason.substr(0, reason.find('\n'))) + "</p>\n";
  if (!p.checks.empty()) {
    out += "<ul class=\"checks\">";
    for (const CheckResult& raw : p.checks) {
      CheckResult c = shownCheck(raw, r.studentView);
      const char* cls = !c.checked ? "unchecked" : c.passed ? "pass" : "fail";
      out += "<li class=\"" + std::string(cls) + "\" title=\"" + htmlEscape(c.message) + "\">" + checkMark(c) +
             "<span class=\"name\">" + htmlEscape(c.name) + "</span>";
      if (r.assignment) out += " <span class=\"pts\">" + number(c.earned) + "/" + number(c.points) + "</span>";
      out += "</li>";
    }
    out += "</ul>\n";
  }
  out += "</article>\n";
  return out;
}

}  // namespace

std::string htmlEscape(const std::string& text) { return markupEscape(text, "&#39;"); }

std::string relativeUrl(const std::string& to, const std::string& fromDir) {
  std::error_code ec;
  fs::path target = fs::absolute(to, ec).lexically_normal();
  fs::path base = fs::absolute(fromDir, ec).lexically_normal();
  fs::path rel = target.lexically_relative(base);
  std::string path = rel.empty() ? target.generic_string() : rel.generic_string();
  std::string out;
  const char* hex = "0123456789ABCDEF";
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '.' || c == '_' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  // A name with a colon before any slash would read as a scheme ("javascript:..."): it was
  // encoded above, and an absolute path (another drive) becomes a file: URL.
  if (rel.empty()) out = "file://" + out;
  return out;
}

std::string classPage(const ClassResult& r, const std::vector<std::string>& pages, const std::string& dir,
                      const std::string& nonce) {
  std::string out = head(r.title + " - class report", nonce, (std::string(kCommonStyle) + kClassStyle).c_str());
  out += "<body>\n<header><h1>" + htmlEscape(r.title) + "</h1><p>";
  size_t n = r.programs.size() - r.missing;
  out += std::to_string(n) + " program" + (n == 1 ? "" : "s") + ": " + std::to_string(r.passed) + " passed, " +
         std::to_string(r.failed) + " failed";
  if (r.errors) out += ", " + std::to_string(r.errors) + " not graded";
  if (r.skipped) out += ", " + std::to_string(r.skipped) + " skipped";
  if (r.missing) out += "; " + std::to_string(r.missing) + " with no submission";
  out += ". Graded " + htmlEscape(r.timestamp) + " by rb test.</p></header>\n";
  if (!r.warnings.empty() || (!r.confinement.empty() && !r.studentView)) {
    out += "<div class=\"warnings\">";
    for (const std::string& w : r.warnings) out += "<p>warning: " + htmlEscape(w) + "</p>";
    if (!r.confinement.empty() && !r.studentView) out += "<p>note: " + htmlEscape(r.confinement) + "</p>";
    out += "</div>\n";
  }
  std::set<std::string> checkNames;
  for (const ProgramResult& p : r.programs)
    for (const CheckResult& c : p.checks) checkNames.insert(shownCheck(c, r.studentView).name);
  out += "<div id=\"controls\">\n";
  out += "<label>Name <input id=\"f-name\" type=\"search\" placeholder=\"student or file\"></label>\n";
  out += "<label>Points from <input id=\"f-min\" type=\"number\" step=\"any\"> to <input id=\"f-max\" "
         "type=\"number\" step=\"any\"></label>\n";
  out += "<label>Result <select id=\"f-verdict\"><option value=\"\">any</option>";
  for (const char* v : {"pass", "fail", "error", "skip", "missing"})
    out += "<option value=\"" + std::string(v) + "\">" + verdictText(v) + "</option>";
  out += "</select></label>\n<label>Failed check <select id=\"f-check\"><option value=\"\">any</option>";
  for (const std::string& c : checkNames) out += "<option value=\"" + htmlEscape(c) + "\">" + htmlEscape(c) + "</option>";
  out += "</select></label>\n<label>Sort by <select id=\"sort\"><option value=\"file\">file</option>"
         "<option value=\"name\">name</option><option value=\"points-desc\">points, most first</option>"
         "<option value=\"points-asc\">points, fewest first</option><option value=\"result\">result, failed "
         "first</option></select></label>\n<span id=\"shown\" role=\"status\"></span>\n</div>\n<main id=\"cards\">\n";
  for (size_t i = 0; i < r.programs.size(); ++i) out += card(r, i, i < pages.size() ? pages[i] : "", dir);
  out += "</main>\n<script nonce=\"" + nonce + "\">" + kClassScript + "</script>\n</body>\n</html>\n";
  return out;
}

std::string programPage(const ClassResult& r, size_t index, const std::string* source, const std::string& dir,
                        const std::string& nonce) {
  const ProgramResult& p = r.programs[index];
  std::string pageDir = (fs::path(dir) / "programs").string();
  std::string name = displayName(p);
  std::string out = head(name + " - " + r.title, nonce, (std::string(kCommonStyle) + kProgramStyle).c_str());
  out += "<body>\n<header><p><a href=\"../index.html\" id=\"back\">&#8592; " + htmlEscape(r.title) +
         ": the class</a></p><h1>" + htmlEscape(name) + "</h1><p>";
  if (!p.student.empty()) out += htmlEscape(p.program) + " &#183; ";
  out += verdictBadge(p.verdict);
  if (r.assignment) out += " &#183; " + number(p.points) + " of " + number(p.maxPoints) + " points";
  bool ran = p.verdict != "skip" && p.verdict != "missing" && !(p.checks.empty() && p.verdict == "fail");
  if (ran) {
    char buf[64];
    std::snprintf(buf, sizeof buf, " &#183; %llu steps, %.2f s", static_cast<unsigned long long>(p.steps), p.seconds);
    out += buf;
  }
  out += "</p></header>\n<main>\n";

  // The checks.
  if (!p.notes.empty() || !p.gate.empty() || (p.checks.empty() && !p.reason.empty())) {
    out += "<section id=\"notes\" class=\"notes\">";
    if (!p.gate.empty()) out += "<p>" + htmlEscape(p.gate) + " (no check counts)</p>";
    else if (p.checks.empty()) out += "<p>" + htmlEscape(p.reason) + "</p>";
    for (const std::string& note : p.notes) out += "<p>note: " + htmlEscape(note) + "</p>";
    out += "</section>\n";
  }
  if (!p.checks.empty()) {
    out += "<section id=\"checks\"><h2>Checks</h2>\n<table class=\"checks\"><tr><th>result</th><th>check</th>";
    if (r.assignment) out += "<th>points</th>";
    out += "<th>what rb found</th></tr>\n";
    for (const CheckResult& raw : p.checks) {
      CheckResult c = shownCheck(raw, r.studentView);
      const char* cls = !c.checked ? "unchecked" : c.passed ? "pass" : "fail";
      out += "<tr class=\"" + std::string(cls) + "\"><td>" + checkMark(c) + "</td><td>" +
             htmlEscape(c.name) + (c.hidden ? " (hidden)" : "") + (c.required ? " (required)" : "") + "</td>";
      if (r.assignment) out += "<td>" + number(c.earned) + " / " + number(c.points) + "</td>";
      out += "<td>" + htmlEscape(c.message);
      if (!c.note.empty()) out += "<br>" + htmlEscape(c.note);
      if (!c.passed && !c.hint.empty()) out += "<div class=\"hint\">hint: " + htmlEscape(c.hint) + "</div>";
      for (const std::string& f : c.feedback) out += "<div class=\"feedback\">" + htmlEscape(f) + "</div>";
      out += "</td></tr>\n";
    }
    out += "</table></section>\n";
  }

  // The pictures and the replay.
  if (!p.picture.empty() || !p.screen.empty()) {
    out += "<section id=\"pictures\"><h2>Pictures</h2>\n";
    if (!p.picture.empty())
      out += "<figure>" +
             imageTag(p.picture, pageDir,
                      r.studentView ? "the run over its final screen" : "the run compared with the solution", "") +
             "<figcaption>" +
             htmlEscape(p.pictureCaption.empty() ? std::string("The run and what the assignment asked for.")
                                                 : p.pictureCaption) +
             "</figcaption></figure>\n";
    if (!p.screen.empty())
      out += "<figure>" + imageTag(p.screen, pageDir, "the final screen", "") +
             "<figcaption>The final screen, as the program left it.</figcaption></figure>\n";
    out += "</section>\n";
  }
  if (!p.replay.empty()) {
    std::string url = htmlEscape(relativeUrl(p.replay, pageDir));
    out += "<section id=\"replay\"><h2>Replay</h2>\n";
    std::string ext = fs::path(p.replay).extension().string();
    if (ext == ".html" || ext == ".htm")
      out += "<iframe class=\"replay\" src=\"" + url + "\" title=\"the run's replay\"></iframe>\n";
    else
      out += "<img src=\"" + url + "\" alt=\"the run's replay\">\n";
    out += "<p><a href=\"" + url + "\">Open the replay on its own</a></p></section>\n";
  }

  // The source, with the lines where the run went wrong marked.
  out += "<section id=\"source\"><h2>Source</h2>\n";
  if (!source) {
    out += p.verdict == "missing" ? "<p>No submission.</p>\n"
                                  : "<p>" + htmlEscape(p.program) + " could not be read.</p>\n";
  } else {
    out += "<div class=\"source\" tabindex=\"0\" role=\"region\" aria-label=\"source\">";
    std::string text = source->substr(0, kSourceCap);
    size_t line = 1, mark = 0;
    for (size_t at = 0; at < text.size() || line == 1;) {
      size_t end = text.find('\n', at);
      if (end == std::string::npos) end = text.size();
      std::string lineText = text.substr(at, end - at);
      if (!lineText.empty() && lineText.back() == '\r') lineText.pop_back();
      while (mark < p.marks.size() && p.marks[mark].line < line) ++mark;
      bool bad = mark < p.marks.size() && p.marks[mark].line == line;
      out += "<span class=\"l" + std::string(bad ? " bad" : "") + "\" id=\"L" + std::to_string(line) +
             "\"><span class=\"n\">" + std::to_string(line) + "</span>" + htmlEscape(lineText) + "</span>";
      for (; mark < p.marks.size() && p.marks[mark].line == line; ++mark)
        out += "<span class=\"msg\">&#8593; " + htmlEscape(p.marks[mark].message) + "</span>";
      ++line;
      at = end + 1;
      if (end == text.size()) break;
    }
    out += "</div>\n";
    if (source->size() > kSourceCap) out += "<p>(cut after 1 MB)</p>\n";
  }
  out += "</section>\n";

  if (!p.output.empty()) {
    out += "<section id=\"output\"><h2>Output</h2>\n";
    if (!p.inputs.empty()) out += "<p>&gt; marks a line where input showed its prompt and read [text].</p>\n";
    out += "<pre tabindex=\"0\" role=\"region\" aria-label=\"output\">" + htmlEscape(outputTranscript(p)) +
           "</pre></section>\n";
  }
  if (!p.errors.empty())
    out += "<section id=\"errors\"><h2>Error output</h2>\n<pre tabindex=\"0\" role=\"region\" aria-label=\"error "
           "output\">" + htmlEscape(p.errors) + "</pre></section>\n";
  if (p.verdict != "missing" && p.verdict != "skip")
    out += "<section id=\"feedback\"><h2>Feedback for the student</h2>\n<p>What rb test --feedback writes for "
           "this program.</p>\n<pre tabindex=\"0\" role=\"region\" aria-label=\"feedback\">" +
           htmlEscape(studentFeedback(p, r)) + "</pre></section>\n";
  out += "</main>\n</body>\n</html>\n";
  return out;
}

bool writeHtmlReport(const ClassResult& r, const std::vector<std::string>& paths, const std::string& dir,
                     std::string& error) {
  std::string pagesDir = (fs::path(dir) / "programs").string();
  if (!render::makeFolder(dir, error) || !render::makeFolder(pagesDir, error)) return false;
  std::string nonce = nonceText();
  std::vector<std::string> pages;
  std::set<std::string> used;
  for (size_t i = 0; i < r.programs.size(); ++i) {
    const ProgramResult& p = r.programs[i];
    std::string base = fs::path(p.name.empty() ? reportName(p.program, paths) : p.name).replace_extension("").string();
    if (base.empty()) base = "program";
    std::string file = base + ".html";
    for (int k = 2; !used.insert(file).second; ++k) file = base + "-" + std::to_string(k) + ".html";
    // The text as graded, read before any run; a file rb did not read (a link leading out of
    // the class folder, a FIFO) shows none.
    std::string page = programPage(r, i, p.sourceRead ? &p.source : nullptr, dir, nonce);
    if (!render::writeFileBytes((fs::path(pagesDir) / file).string(), page.data(), page.size(), error)) return false;
    pages.push_back(relativeUrl((fs::path(pagesDir) / file).string(), dir));
  }
  std::string index = classPage(r, pages, dir, nonce);
  return render::writeFileBytes((fs::path(dir) / "index.html").string(), index.data(), index.size(), error);
}

}  // namespace rb::grade
