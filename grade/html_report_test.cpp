#include "html_report.h"

#include <catch2/catch.hpp>

using namespace rb::grade;

namespace {

ClassResult hostileClass() {
  ClassResult r;
  r.title = "square <b>";
  r.timestamp = "2026-11-26T10:00:00Z";
  r.assignment = true;
  ProgramResult p;
  p.program = "class/<script>alert(1)</script>.bas";
  p.student = "Eve\" onmouseover=\"alert(2)";
  p.verdict = "fail";
  p.reason = "output: expected <img src=x onerror=alert(3)>";
  CheckResult c;
  c.name = "output </script><script>alert(4)</script>";
  c.message = p.reason;
  c.points = 2;
  p.checks = {c};
  p.maxPoints = 2;
  p.output = "</pre><script>alert(5)</script>\n";
  p.errors = "<iframe src=javascript:alert(6)>";
  p.marks = {{2, "error <b>here</b>"}};
  r.programs = {p};
  r.failed = 1;
  return r;
}

}  // namespace

TEST_CASE("htmlEscape escapes markup, quotes and stray bytes", "[html]") {
  CHECK(htmlEscape("<a href='x'>\"&\"</a>") == "&lt;a href=&#39;x&#39;&gt;&quot;&amp;&quot;&lt;/a&gt;");
  CHECK(htmlEscape(std::string("caf\xE9")) == "caf\xC3\xA9");           // Latin-1 read as such
  CHECK(htmlEscape(std::string("a\x01z")) == "a^Az");                    // control character: caret notation
  CHECK(htmlEscape("tab\tand\nline") == "tab\tand\nline");
}

TEST_CASE("relativeUrl links relative to the page and encodes what a URL cannot carry", "[html]") {
  CHECK(relativeUrl("out/pictures/a.png", "out") == "pictures/a.png");
  CHECK(relativeUrl("out/pictures/a.png", "out/programs") == "../pictures/a.png");
  CHECK(relativeUrl("out/pictures/a b#?.png", "out") == "pictures/a%20b%23%3F.png");
  CHECK(relativeUrl("out/javascript:alert(1).png", "out") == "javascript%3Aalert%281%29.png");
  CHECK(relativeUrl("out/\"><x.png", "out") == "%22%3E%3Cx.png");
}

TEST_CASE("nothing a student wrote reaches the pages as markup", "[html]") {
  ClassResult r = hostileClass();
  std::string source = "print 1\n</div><script>alert(7)</script>\nend\n";
  std::string page = programPage(r, 0, &source, "out", "n0nce");
  std::string index = classPage(r, {"programs/x.html"}, "out", "n0nce");
  for (const std::string& html : {page, index}) {
    // The page's own script is the only one, and carries the nonce.
    size_t scripts = 0;
    for (size_t at = html.find("<script"); at != std::string::npos; at = html.find("<script", at + 1)) {
      ++scripts;
      CHECK(html.compare(at, 21, "<script nonce=\"n0nce\"") == 0);
    }
    CHECK(scripts <= 1);
    CHECK(html.find("<img src=x") == std::string::npos);
    CHECK(html.find("<iframe src=javascript") == std::string::npos);
    CHECK(html.find("\" onmouseover=") == std::string::npos);
    CHECK(html.find("<b>") == std::string::npos);
    CHECK(html.find("script-src 'nonce-n0nce'") != std::string::npos);
  }
  CHECK(page.find("&lt;/div&gt;&lt;script&gt;alert(7)") != std::string::npos);
  CHECK(page.find("Eve&quot; onmouseover=&quot;alert(2)") != std::string::npos);
  CHECK(index.find("data-name=\"Eve&quot; onmouseover=&quot;alert(2) class/&lt;script&gt;") != std::string::npos);
}

TEST_CASE("the program page marks the lines where the run went wrong", "[html]") {
  ClassResult r = hostileClass();
  std::string source = "a = 1\r\nb = 1/0\r\nend";
  std::string page = programPage(r, 0, &source, "out", "n");
  CHECK(page.find("<span class=\"l\" id=\"L1\"><span class=\"n\">1</span>a = 1</span>") != std::string::npos);
  CHECK(page.find("<span class=\"l bad\" id=\"L2\"><span class=\"n\">2</span>b = 1/0</span>"
                  "<span class=\"msg\">&#8593; error &lt;b&gt;here&lt;/b&gt;</span>") != std::string::npos);
  CHECK(page.find("id=\"L3\"") != std::string::npos);
  CHECK(page.find("id=\"L4\"") == std::string::npos);
  std::string missing = programPage(r, 0, nullptr, "out", "n");
  CHECK(missing.find("could not be read") != std::string::npos);
}

TEST_CASE("a card carries what the page sorts and filters by", "[html]") {
  ClassResult r = hostileClass();
  r.programs[0].points = 1.5;
  r.programs[0].screen = "out/pictures/x.screen.png";
  std::string index = classPage(r, {"programs/x.html"}, "out", "n");
  CHECK(index.find("data-points=\"1.5\"") != std::string::npos);
  CHECK(index.find("data-verdict=\"fail\"") != std::string::npos);
  CHECK(index.find("data-failed=\"output &lt;/script&gt;&lt;script&gt;alert(4)&lt;/script&gt;\"") != std::string::npos);
  CHECK(index.find("<img src=\"pictures/x.screen.png\"") != std::string::npos);
  CHECK(index.find("<a class=\"open\" href=\"programs/x.html\">") != std::string::npos);
  CHECK(index.find("<option value=\"output &lt;/script&gt;") != std::string::npos);
}
