#pragma once
// Turns one source file into tokens. Comments (//, ', rem, /* */) are dropped; each line end is
// a Newline token, so statements are line-based.

#include <vector>

#include "base/diagnostic.h"
#include "lang/token.h"

namespace rb {

/// Tokenizes `sources.file(fileIndex)`. Lexical errors go to `diags`; the bad characters are
/// skipped so that parsing can go on.
std::vector<Token> lex(const SourceSet& sources, uint32_t fileIndex, DiagnosticList& diags);

}  // namespace rb
