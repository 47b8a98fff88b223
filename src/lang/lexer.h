// The .geo lexer: turns text into tokens on demand (no token array, so a 256 MiB
// file costs no memory beyond its text). Never throws; bad input becomes
// Tok::Error tokens plus diagnostics.
#pragma once

#include <cstdint>
#include <string_view>

#include "lang/diagnostics.h"
#include "lang/source.h"
#include "lang/token.h"

namespace sm::lang {

class Lexer {
 public:
  Lexer(const SourceManager& sources, FileId file, Diagnostics& diags);

  /// The next token; Tok::Eof forever at the end.
  Token next();
  std::string_view text(const Token& t) const { return text_.substr(t.range.begin, t.range.end - t.range.begin); }
  std::string_view source() const { return text_; }
  FileId file() const { return file_; }
  /// True once an unterminated string or comment swallowed the rest of the
  /// file (the parser then stays quiet about the missing end).
  bool truncated() const { return truncated_; }

 private:
  SourceRange range(std::uint32_t b, std::uint32_t e) const { return {file_, b, e}; }
  bool skip_space_and_comments();
  Token lex_number();
  Token lex_identifier();
  Token lex_string();
  Token lex_invalid();

  std::string_view text_;
  FileId file_;
  Diagnostics* diags_;
  std::uint32_t pos_ = 0;
  bool truncated_ = false;
};

/// The value of a Number token's text (Gmsh rules: `1.`, `.5`, `1.5e-3`, `2E4`).
/// Returns false when the text is out of the double range.
bool number_value(std::string_view text, double& value);

}  // namespace sm::lang
