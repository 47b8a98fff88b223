// Token names for messages and the reserved-word table (with Gmsh's synonyms).
#include "lang/token.h"

#include <algorithm>
#include <array>
#include <utility>

namespace sm::lang {

namespace {

struct KeywordEntry {
  std::string_view text;
  Tok kind;
};

constexpr auto make_keywords() {
  std::array entries = {
#define SM_KW(kind, text) KeywordEntry{text, Tok::kind},
      SM_GEO_KEYWORDS(SM_KW)
#undef SM_KW
  };
  std::sort(entries.begin(), entries.end(),
            [](const KeywordEntry& a, const KeywordEntry& b) { return a.text < b.text; });
  return entries;
}
constexpr auto kKeywords = make_keywords();

}  // namespace

Tok keyword_from_text(std::string_view text) {
  const auto it = std::lower_bound(kKeywords.begin(), kKeywords.end(), text,
                                   [](const KeywordEntry& e, std::string_view t) { return e.text < t; });
  return it != kKeywords.end() && it->text == text ? it->kind : Tok::Ident;
}

bool is_keyword(Tok kind) { return kind >= Tok::For && kind < Tok::kCount; }

std::string_view tok_name(Tok kind) {
  switch (kind) {
    case Tok::Eof: return "end of file";
    case Tok::Error: return "invalid text";
    case Tok::Ident: return "identifier";
    case Tok::Number: return "number";
    case Tok::String: return "string";
    case Tok::Constant: return "built-in constant";
    case Tok::LParen: return "'('";
    case Tok::RParen: return "')'";
    case Tok::LBracket: return "'['";
    case Tok::RBracket: return "']'";
    case Tok::LBrace: return "'{'";
    case Tok::RBrace: return "'}'";
    case Tok::Comma: return "','";
    case Tok::Semicolon: return "';'";
    case Tok::Colon: return "':'";
    case Tok::ColonColon: return "'::'";
    case Tok::Dot: return "'.'";
    case Tok::Hash: return "'#'";
    case Tok::Tilde: return "'~'";
    case Tok::Question: return "'?'";
    case Tok::Plus: return "'+'";
    case Tok::Minus: return "'-'";
    case Tok::Star: return "'*'";
    case Tok::Slash: return "'/'";
    case Tok::Percent: return "'%'";
    case Tok::Caret: return "'^'";
    case Tok::Not: return "'!'";
    case Tok::Amp: return "'&'";
    case Tok::Pipe: return "'|'";
    case Tok::AmpAmp: return "'&&'";
    case Tok::PipePipe: return "'||'";
    case Tok::Less: return "'<'";
    case Tok::Greater: return "'>'";
    case Tok::LessEq: return "'<='";
    case Tok::GreaterEq: return "'>='";
    case Tok::EqEq: return "'=='";
    case Tok::NotEq: return "'!='";
    case Tok::ShiftLeft: return "'<<'";
    case Tok::ShiftRight: return "'>>'";
    case Tok::PlusPlus: return "'++'";
    case Tok::MinusMinus: return "'--'";
    case Tok::Assign: return "'='";
    case Tok::PlusAssign: return "'+='";
    case Tok::MinusAssign: return "'-='";
    case Tok::StarAssign: return "'*='";
    case Tok::SlashAssign: return "'/='";
    case Tok::kCount: return "?";
    default: break;
  }
  // Keywords: the first spelling in the table order of SM_GEO_KEYWORDS.
#define SM_KW(k, text) \
  if (kind == Tok::k) return "'" text "'";
  SM_GEO_KEYWORDS(SM_KW)
#undef SM_KW
  return "keyword";
}

}  // namespace sm::lang
