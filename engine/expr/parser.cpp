#include "expr/parser.h"

#include "expr/lexer.h"

namespace sdfwb::expr {
namespace {

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  Program program() {
    Program result;
    while (true) {
      if (!at(TokenKind::Semicolon) && !at(TokenKind::End)) result.statements.push_back(statement());
      if (at(TokenKind::End)) break;
      if (!at(TokenKind::Semicolon)) fail("expected an operator, ';' or the end of the formula");
      next();
    }
    result.end = peek().where;
    return result;
  }

 private:
  const Token& peek() const { return tokens_[pos_]; }
  bool at(TokenKind kind) const { return peek().kind == kind; }
  const Token& next() { return tokens_[pos_ < tokens_.size() - 1 ? pos_++ : pos_]; }
  [[noreturn]] void fail(const std::string& message) const { throw Error(peek().where, message); }

  // Every recursive rule and every operator of a chain enters one level; the
  // syntax tree is then never deeper than kMaxExpressionDepth.
  // Levels entered by one rule (one for a recursive rule, one per operator of a
  // chain), left when the rule returns.
  class Levels {
   public:
    explicit Levels(Parser& parser, int count = 1) : parser_(parser) { enter(count); }
    ~Levels() { parser_.depth_ -= count_; }
    Levels(const Levels&) = delete;
    Levels& operator=(const Levels&) = delete;

    void enter(int count = 1) {
      count_ += count;
      parser_.depth_ += count;
      if (parser_.depth_ > kMaxExpressionDepth) {
        parser_.fail("the formula nests deeper than " + std::to_string(kMaxExpressionDepth) +
                     " levels (parentheses, signs and chained operators)");
      }
    }

   private:
    Parser& parser_;
    int count_ = 0;
  };

  Statement statement() {
    Statement s;
    s.where = peek().where;
    if (at(TokenKind::Let)) {
      next();
      s.kind = Statement::Kind::Let;
      if (!at(TokenKind::Identifier)) fail("expected a name after 'let'");
      s.nameWhere = peek().where;
      s.name = next().text;
      if (!at(TokenKind::Equals)) fail("expected '=' after 'let " + s.name + "'");
      next();
      s.value = expression();
      return s;
    }
    s.value = expression();
    if (at(TokenKind::Equals)) {
      next();
      s.kind = Statement::Kind::Equation;
      s.rhsWhere = peek().where;
      s.rhs = expression();
    }
    return s;
  }

  std::unique_ptr<Expr> binary(char op, SourceLocation where, std::unique_ptr<Expr> lhs,
                               std::unique_ptr<Expr> rhs) {
    auto e = std::make_unique<Expr>();
    e->kind = Expr::Kind::Binary;
    e->op = op;
    e->where = where;
    e->operands.push_back(std::move(lhs));
    e->operands.push_back(std::move(rhs));
    return e;
  }

  std::unique_ptr<Expr> expression() {
    Levels levels(*this);
    auto lhs = term();
    while (at(TokenKind::Plus) || at(TokenKind::Minus)) {
      const Token& op = next();
      levels.enter();
      lhs = binary(op.text[0], op.where, std::move(lhs), term());
    }
    return lhs;
  }

  std::unique_ptr<Expr> term() {
    Levels levels(*this, 0);
    auto lhs = unary();
    while (at(TokenKind::Star) || at(TokenKind::Slash)) {
      const Token& op = next();
      levels.enter();
      lhs = binary(op.text[0], op.where, std::move(lhs), unary());
    }
    return lhs;
  }

  std::unique_ptr<Expr> unary() {
    const Levels level(*this);
    if (at(TokenKind::Plus)) {
      next();
      return unary();
    }
    if (at(TokenKind::Minus)) {
      auto e = std::make_unique<Expr>();
      e->kind = Expr::Kind::Negate;
      e->where = next().where;
      e->operands.push_back(unary());
      return e;
    }
    return power();
  }

  std::unique_ptr<Expr> power() {
    auto base = postfix();
    if (!at(TokenKind::Caret)) return base;
    const SourceLocation where = next().where;
    return binary('^', where, std::move(base), unary());
  }

  std::unique_ptr<Expr> postfix() {
    Levels levels(*this, 0);
    auto e = primary();
    while (at(TokenKind::Dot)) {
      levels.enter();
      auto member = std::make_unique<Expr>();
      member->kind = Expr::Kind::Component;
      member->where = next().where;
      if (!at(TokenKind::Identifier)) fail("expected a component name such as x after '.'");
      member->name = next().text;
      member->operands.push_back(std::move(e));
      e = std::move(member);
    }
    return e;
  }

  std::unique_ptr<Expr> primary() {
    auto e = std::make_unique<Expr>();
    e->where = peek().where;
    switch (peek().kind) {
      case TokenKind::Number:
        e->kind = Expr::Kind::Number;
        e->number = next().number;
        return e;
      case TokenKind::Identifier:
        e->name = next().text;
        if (!at(TokenKind::LeftParen)) {
          e->kind = Expr::Kind::Name;
          return e;
        }
        e->kind = Expr::Kind::Call;
        next();
        if (at(TokenKind::RightParen)) {
          next();
          return e;
        }
        while (true) {
          e->operandLocations.push_back(peek().where);
          e->operands.push_back(expression());
          if (at(TokenKind::RightParen)) break;
          if (!at(TokenKind::Comma)) fail("expected ')' after function arguments");
          next();
        }
        next();
        return e;
      case TokenKind::LeftParen: {
        next();
        auto inner = expression();
        if (!at(TokenKind::RightParen)) fail("expected ')'");
        next();
        return inner;
      }
      case TokenKind::Let:
        fail("'let' must start a statement");
      default:
        fail("expected an expression");
    }
  }

  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

Program parse(std::string_view source) {
  if (source.size() > kMaxFormulaLength) {
    throw Error({}, "the formula is " + std::to_string(source.size()) + " characters long (at most " +
                        std::to_string(kMaxFormulaLength) + ")");
  }
  return Parser(tokenize(source)).program();
}

}  // namespace sdfwb::expr
