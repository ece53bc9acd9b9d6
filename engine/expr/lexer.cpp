#include "expr/lexer.h"

#include <algorithm>
#include <cstdlib>

namespace sdfwb::expr {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isNameStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isNameChar(char c) { return isNameStart(c) || isDigit(c); }

// Decimal exponents beyond this are refused: 1e1000000 would make GMP build a
// million-digit integer before anything could check it.
constexpr long kMaxDecimalExponent = 1000;
// Longer literals and names are refused: a literal of many thousand digits
// makes exact arithmetic (Groebner bases) crawl, and names are quoted in messages.
constexpr std::size_t kMaxNumberDigits = 100;
constexpr std::size_t kMaxNameLength = 100;

class Lexer {
 public:
  explicit Lexer(std::string_view source) : source_(source) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    while (true) {
      skipSpaceAndComments();
      Token token;
      token.where = here();
      if (pos_ >= source_.size()) {
        tokens.push_back(token);
        return tokens;
      }
      const char c = source_[pos_];
      if (isDigit(c) || (c == '.' && pos_ + 1 < source_.size() && isDigit(source_[pos_ + 1]))) {
        lexNumber(token);
      } else if (isNameStart(c)) {
        const std::size_t start = pos_;
        while (pos_ < source_.size() && isNameChar(source_[pos_])) advance();
        if (pos_ - start > kMaxNameLength) {
          throw Error(token.where, "a name of " + std::to_string(pos_ - start) + " characters (at most " +
                                       std::to_string(kMaxNameLength) + ")");
        }
        token.text = std::string(source_.substr(start, pos_ - start));
        token.kind = token.text == "let" ? TokenKind::Let : TokenKind::Identifier;
      } else {
        token.kind = punctuation(c);
        token.text = std::string(1, c);
        advance();
      }
      tokens.push_back(std::move(token));
    }
  }

 private:
  SourceLocation here() const { return {line_, column_}; }

  void advance() {
    if (source_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }

  void skipSpaceAndComments() {
    while (pos_ < source_.size()) {
      const char c = source_[pos_];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        advance();
      } else if (c == '/' && pos_ + 1 < source_.size() && source_[pos_ + 1] == '/') {
        while (pos_ < source_.size() && source_[pos_] != '\n') advance();
      } else {
        return;
      }
    }
  }

  TokenKind punctuation(char c) const {
    switch (c) {
      case '+': return TokenKind::Plus;
      case '-': return TokenKind::Minus;
      case '*': return TokenKind::Star;
      case '/': return TokenKind::Slash;
      case '^': return TokenKind::Caret;
      case '(': return TokenKind::LeftParen;
      case ')': return TokenKind::RightParen;
      case ',': return TokenKind::Comma;
      case '.': return TokenKind::Dot;
      case ';': return TokenKind::Semicolon;
      case '=': return TokenKind::Equals;
      default: break;
    }
    const unsigned char u = static_cast<unsigned char>(c);
    if (u < 0x20 || u >= 0x7f) throw Error(here(), "unexpected character (only ASCII is allowed)");
    throw Error(here(), "unexpected character '" + std::string(1, c) + "'");
  }

  // digits [. digits] [e [+-] digits], or . digits [...]; the value is exact.
  void lexNumber(Token& token) {
    token.kind = TokenKind::Number;
    const std::size_t start = pos_;
    std::string digits;
    long scale = 0;  // value = digits * 10^scale
    while (pos_ < source_.size() && isDigit(source_[pos_])) {
      digits += source_[pos_];
      advance();
    }
    if (pos_ < source_.size() && source_[pos_] == '.') {
      advance();
      while (pos_ < source_.size() && isDigit(source_[pos_])) {
        digits += source_[pos_];
        --scale;
        advance();
      }
    }
    if (pos_ < source_.size() && (source_[pos_] == 'e' || source_[pos_] == 'E')) {
      advance();
      bool negative = false;
      if (pos_ < source_.size() && (source_[pos_] == '+' || source_[pos_] == '-')) {
        negative = source_[pos_] == '-';
        advance();
      }
      if (pos_ >= source_.size() || !isDigit(source_[pos_])) {
        throw Error(here(), "expected digits in the exponent of a number");
      }
      long exponent = 0;
      while (pos_ < source_.size() && isDigit(source_[pos_])) {
        if (exponent <= kMaxDecimalExponent) exponent = exponent * 10 + (source_[pos_] - '0');
        advance();
      }
      if (exponent > kMaxDecimalExponent) throw Error(token.where, "the exponent of this number is too large");
      scale += negative ? -exponent : exponent;
    }
    token.text = std::string(source_.substr(start, pos_ - start));
    const std::size_t significant = digits.size() - std::min(digits.size(), digits.find_first_not_of('0'));
    if (significant > kMaxNumberDigits) {
      throw Error(token.where, "a number of " + std::to_string(significant) + " digits (at most " +
                                   std::to_string(kMaxNumberDigits) + ")");
    }
    mpz_class mantissa(digits, 10);
    mpz_class power;
    mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
    token.number = scale < 0 ? mpq_class(mantissa, power) : mpq_class(mantissa * power);
    token.number.canonicalize();
  }

  std::string_view source_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

}  // namespace

std::string describe(TokenKind kind) {
  switch (kind) {
    case TokenKind::Number: return "a number";
    case TokenKind::Identifier: return "a name";
    case TokenKind::Let: return "'let'";
    case TokenKind::Plus: return "'+'";
    case TokenKind::Minus: return "'-'";
    case TokenKind::Star: return "'*'";
    case TokenKind::Slash: return "'/'";
    case TokenKind::Caret: return "'^'";
    case TokenKind::LeftParen: return "'('";
    case TokenKind::RightParen: return "')'";
    case TokenKind::Comma: return "','";
    case TokenKind::Dot: return "'.'";
    case TokenKind::Semicolon: return "';'";
    case TokenKind::Equals: return "'='";
    case TokenKind::End: return "the end of the formula";
  }
  return "?";
}

std::vector<Token> tokenize(std::string_view source) { return Lexer(source).run(); }

}  // namespace sdfwb::expr
