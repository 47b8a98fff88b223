// The .geo lexer (docs/language.md): comments, numbers without sign, raw
// strings, identifiers/keywords and maximal-munch operators. Linear in the input
// on any bytes; runs of bad bytes give one Error token and one diagnostic.
#include "lang/lexer.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

#include "lang/ast.h"

namespace sm::lang {

namespace {

bool is_space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool is_digit(unsigned char c) { return c >= '0' && c <= '9'; }
bool is_ident_start(unsigned char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_ident_char(unsigned char c) { return is_ident_start(c) || is_digit(c); }

// Characters that start a token (everything else is invalid text).
bool starts_token(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  if (is_space(c) || is_ident_start(c) || is_digit(c)) return true;
  switch (c) {
    case '(': case ')': case '[': case ']': case '{': case '}': case ',': case ';': case ':':
    case '.': case '#': case '~': case '?': case '+': case '-': case '*': case '/': case '%':
    case '^': case '!': case '&': case '|': case '<': case '>': case '=': case '"': case '\'':
      return true;
    default:
      return false;
  }
}

}  // namespace

bool number_value(std::string_view text, double& value) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
  if (r.ec == std::errc() && r.ptr == text.data() + text.size()) return true;
  // from_chars rejects some spellings and reports underflow as an error; strtod
  // (what Gmsh's atof does) settles both. Only overflow to infinity is refused.
  const std::string copy(text);
  errno = 0;
  value = std::strtod(copy.c_str(), nullptr);
  return !(errno == ERANGE && std::isinf(value));
}

Lexer::Lexer(const SourceManager& sources, FileId file, Diagnostics& diags)
    : text_(sources.text(file)), file_(file), diags_(&diags) {}

// Skips whitespace and comments. Returns false if an unterminated /* comment
// ran to the end of the file (already diagnosed).
bool Lexer::skip_space_and_comments() {
  const std::size_t n = text_.size();
  while (pos_ < n) {
    const auto c = static_cast<unsigned char>(text_[pos_]);
    if (is_space(c)) {
      ++pos_;
    } else if (c == '/' && pos_ + 1 < n && text_[pos_ + 1] == '/') {
      const void* nl = std::memchr(text_.data() + pos_, '\n', n - pos_);
      pos_ =
          nl ? static_cast<std::uint32_t>(static_cast<const char*>(nl) - text_.data()) : static_cast<std::uint32_t>(n);
    } else if (c == '/' && pos_ + 1 < n && text_[pos_ + 1] == '*') {
      const std::size_t close = text_.find("*/", pos_ + 2);
      if (close == std::string_view::npos) {
        diags_->report(range(pos_, pos_ + 2), Diag::UnterminatedComment);
        truncated_ = true;
        pos_ = static_cast<std::uint32_t>(n);
        return false;
      }
      pos_ = static_cast<std::uint32_t>(close + 2);
    } else {
      break;
    }
  }
  return true;
}

Token Lexer::next() {
  skip_space_and_comments();
  const std::size_t n = text_.size();
  if (pos_ >= n) return {Tok::Eof, range(static_cast<std::uint32_t>(n), static_cast<std::uint32_t>(n))};
  const auto c = static_cast<unsigned char>(text_[pos_]);
  if (is_ident_start(c)) return lex_identifier();
  if (is_digit(c) || (c == '.' && pos_ + 1 < n && is_digit(static_cast<unsigned char>(text_[pos_ + 1]))))
    return lex_number();
  if (c == '"' || c == '\'') return lex_string();

  const std::uint32_t b = pos_;
  const char c1 = pos_ + 1 < n ? text_[pos_ + 1] : '\0';
  auto tok = [&](Tok k, std::uint32_t len) {
    pos_ += len;
    return Token{k, range(b, pos_)};
  };
  switch (c) {
    case '(': return tok(Tok::LParen, 1);
    case ')': return tok(Tok::RParen, 1);
    case '[': return tok(Tok::LBracket, 1);
    case ']': return tok(Tok::RBracket, 1);
    case '{': return tok(Tok::LBrace, 1);
    case '}': return tok(Tok::RBrace, 1);
    case ',': return tok(Tok::Comma, 1);
    case ';': return tok(Tok::Semicolon, 1);
    case ':': return c1 == ':' ? tok(Tok::ColonColon, 2) : tok(Tok::Colon, 1);
    case '.':  // "..." is Gmsh's other spelling of ':' (Parser/Gmsh.l: both are tDOTS): {1 ... 150}
      return c1 == '.' && pos_ + 2 < n && text_[pos_ + 2] == '.' ? tok(Tok::Colon, 3) : tok(Tok::Dot, 1);
    case '#': return tok(Tok::Hash, 1);
    case '~': return tok(Tok::Tilde, 1);
    case '?': return tok(Tok::Question, 1);
    case '+': return c1 == '=' ? tok(Tok::PlusAssign, 2) : c1 == '+' ? tok(Tok::PlusPlus, 2) : tok(Tok::Plus, 1);
    case '-': return c1 == '=' ? tok(Tok::MinusAssign, 2) : c1 == '-' ? tok(Tok::MinusMinus, 2) : tok(Tok::Minus, 1);
    case '*': return c1 == '=' ? tok(Tok::StarAssign, 2) : tok(Tok::Star, 1);
    case '/': return c1 == '=' ? tok(Tok::SlashAssign, 2) : tok(Tok::Slash, 1);
    case '%': return tok(Tok::Percent, 1);
    case '^': return tok(Tok::Caret, 1);
    case '!': return c1 == '=' ? tok(Tok::NotEq, 2) : tok(Tok::Not, 1);
    case '&': return c1 == '&' ? tok(Tok::AmpAmp, 2) : tok(Tok::Amp, 1);
    case '|': return c1 == '|' ? tok(Tok::PipePipe, 2) : tok(Tok::Pipe, 1);
    case '<': return c1 == '=' ? tok(Tok::LessEq, 2) : c1 == '<' ? tok(Tok::ShiftLeft, 2) : tok(Tok::Less, 1);
    case '>': return c1 == '=' ? tok(Tok::GreaterEq, 2) : c1 == '>' ? tok(Tok::ShiftRight, 2) : tok(Tok::Greater, 1);
    case '=': return c1 == '=' ? tok(Tok::EqEq, 2) : tok(Tok::Assign, 1);
    default: return lex_invalid();
  }
}

// number := digits ["." digits*] [exp] | "." digits [exp] ; exp := [eE] [+-] digits
Token Lexer::lex_number() {
  const std::size_t n = text_.size();
  const std::uint32_t b = pos_;
  while (pos_ < n && is_digit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  if (pos_ < n && text_[pos_] == '.') {
    ++pos_;
    while (pos_ < n && is_digit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  if (pos_ < n && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
    std::size_t p = pos_ + 1;
    if (p < n && (text_[p] == '+' || text_[p] == '-')) ++p;
    if (p < n && is_digit(static_cast<unsigned char>(text_[p]))) {  // else: `2e` is 2 then `e`
      while (p < n && is_digit(static_cast<unsigned char>(text_[p]))) ++p;
      pos_ = static_cast<std::uint32_t>(p);
    }
  }
  return {Tok::Number, range(b, pos_)};
}

Token Lexer::lex_identifier() {
  const std::size_t n = text_.size();
  const std::uint32_t b = pos_;
  while (pos_ < n && is_ident_char(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  const std::string_view word = text_.substr(b, pos_ - b);
  Tok kind = keyword_from_text(word);
  if (kind == Tok::Ident && constant_from_text(word) != Constant::kCount) kind = Tok::Constant;
  return {kind, range(b, pos_)};
}

// string := '"' (any but '"')* '"' | "'" (any but "'")* "'"   (no escapes; may span lines)
Token Lexer::lex_string() {
  const std::uint32_t b = pos_;
  const char quote = text_[pos_];
  const std::size_t close = text_.find(quote, pos_ + 1);
  if (close == std::string_view::npos) {
    diags_->report(range(b, b + 1), Diag::UnterminatedString, quote == '"' ? "'\"'" : "\"'\"");
    truncated_ = true;
    pos_ = static_cast<std::uint32_t>(text_.size());
    return {Tok::Error, range(b, pos_)};
  }
  pos_ = static_cast<std::uint32_t>(close + 1);
  return {Tok::String, range(b, pos_)};
}

// A run of characters that cannot start a token: one Error token, one message
// about its first character.
Token Lexer::lex_invalid() {
  const std::size_t n = text_.size();
  const std::uint32_t b = pos_;
  const auto first = static_cast<unsigned char>(text_[b]);
  std::size_t first_len = 1;
  bool printable = first >= 0x20 && first < 0x7F;
  if (first >= 0x80) {  // a whole valid UTF-8 character is quoted; an invalid byte is shown in hex
    std::size_t len = first >= 0xC2 && first <= 0xDF   ? 2
                      : first >= 0xE0 && first <= 0xEF ? 3
                      : first >= 0xF0 && first <= 0xF4 ? 4
                                                       : 0;
    bool ok = len > 0 && b + len <= n;
    for (std::size_t k = 1; ok && k < len; ++k) ok = (static_cast<unsigned char>(text_[b + k]) & 0xC0) == 0x80;
    if (ok) {
      printable = true;
      first_len = len;
    }
  }
  pos_ = static_cast<std::uint32_t>(b + first_len);
  while (pos_ < n && !starts_token(text_, pos_)) ++pos_;
  if (printable)
    diags_->report(range(b, pos_), Diag::UnexpectedCharacter, text_.substr(b, first_len));
  else
    diags_->report(range(b, pos_), Diag::InvalidByte, static_cast<unsigned>(first));
  return {Tok::Error, range(b, pos_)};
}

}  // namespace sm::lang
