#include "text.h"

#include <catch2/catch.hpp>

using rb::grade::toUtf8;

TEST_CASE("text becomes UTF-8 without losing Latin-1 bytes", "[grade][text]") {
  CHECK(toUtf8("plain") == "plain");
  CHECK(toUtf8("caf\xC3\xA9") == "caf\xC3\xA9");                // UTF-8 stays
  CHECK(toUtf8("caf\xE9") == "caf\xC3\xA9");                    // Latin-1 é becomes UTF-8 é
  CHECK(toUtf8("\xE2\x82") == "\xC3\xA2\xC2\x82");              // a cut sequence: byte by byte
  CHECK(toUtf8("\xC0\x80") == "\xC3\x80\xC2\x80");              // an overlong encoding is not UTF-8
  CHECK(toUtf8("\xED\xA0\x80") == "\xC3\xAD\xC2\xA0\xC2\x80");  // nor is a surrogate
  CHECK(toUtf8("a\x01z") == "a\x01z");
  CHECK(toUtf8("a\x01z", true) == "a\xEF\xBF\xBDz");            // XML cannot carry ^A
  CHECK(toUtf8("tab\tnl\n", true) == "tab\tnl\n");
}
