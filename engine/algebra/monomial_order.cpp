#include "algebra/monomial_order.h"

#include <numeric>
#include <stdexcept>

namespace sdfwb::algebra {

MonomialOrder::MonomialOrder(Kind kind) : kind_(kind) {}
MonomialOrder::~MonomialOrder() = default;
MonomialOrder::MonomialOrder(const MonomialOrder&) = default;
MonomialOrder::MonomialOrder(MonomialOrder&&) noexcept = default;
MonomialOrder& MonomialOrder::operator=(const MonomialOrder&) = default;
MonomialOrder& MonomialOrder::operator=(MonomialOrder&&) noexcept = default;

MonomialOrder MonomialOrder::lex() { return MonomialOrder(Kind::lex); }
MonomialOrder MonomialOrder::deglex() { return MonomialOrder(Kind::deglex); }
MonomialOrder MonomialOrder::degrevlex() { return MonomialOrder(Kind::degrevlex); }

MonomialOrder MonomialOrder::weighted(std::vector<std::int64_t> weights,
                                      const MonomialOrder& tie_break) {
  for (std::int64_t w : weights) {
    if (w < 0) throw std::invalid_argument("weighted order: weights must be non-negative");
  }
  MonomialOrder order(Kind::weighted);
  order.weights_ = std::move(weights);
  order.tie_break_.push_back(tie_break);
  return order;
}

MonomialOrder MonomialOrder::block(std::vector<Block> blocks) {
  if (blocks.empty()) throw std::invalid_argument("block order: no blocks");
  MonomialOrder order(Kind::block);
  order.blocks_ = std::move(blocks);
  return order;
}

MonomialOrder MonomialOrder::elimination(std::size_t eliminated,
                                         const MonomialOrder& eliminated_order,
                                         const MonomialOrder& rest_order) {
  // The rest block's size is only known with the ring; 0 here means "all
  // remaining variables" and is resolved by the block's own checks.
  return block({Block{eliminated, eliminated_order}, Block{0, rest_order}});
}

std::optional<MonomialOrder> MonomialOrder::from_name(std::string_view name) {
  if (name == "lex") return lex();
  if (name == "deglex") return deglex();
  if (name == "degrevlex") return degrevlex();
  return std::nullopt;
}

namespace {

// Sizes of the blocks for `n` variables; a trailing size 0 takes the rest.
std::vector<std::size_t> block_sizes(const std::vector<MonomialOrder::Block>& blocks,
                                     std::size_t n) {
  std::vector<std::size_t> sizes;
  std::size_t used = 0;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    std::size_t size = blocks[i].size;
    if (size == 0 && i + 1 == blocks.size() && used <= n) size = n - used;
    sizes.push_back(size);
    used += size;
  }
  if (used != n) {
    throw std::invalid_argument("block order: block sizes add up to " + std::to_string(used) +
                                " but the ring has " + std::to_string(n) + " variables");
  }
  return sizes;
}

}  // namespace

void MonomialOrder::check_fits(std::size_t n) const {
  switch (kind_) {
    case Kind::lex:
    case Kind::deglex:
    case Kind::degrevlex:
      return;
    case Kind::weighted:
      if (weights_.size() != n) {
        throw std::invalid_argument("weighted order: " + std::to_string(weights_.size()) +
                                    " weights for " + std::to_string(n) + " variables");
      }
      tie_break_.front().check_fits(n);
      return;
    case Kind::block: {
      std::vector<std::size_t> sizes = block_sizes(blocks_, n);
      for (std::size_t i = 0; i < blocks_.size(); ++i) blocks_[i].order.check_fits(sizes[i]);
      return;
    }
  }
}

std::vector<std::vector<std::int64_t>> MonomialOrder::matrix(std::size_t n) const {
  std::vector<std::vector<std::int64_t>> rows;
  auto unit = [n](std::size_t i, std::int64_t value) {
    std::vector<std::int64_t> row(n, 0);
    row[i] = value;
    return row;
  };
  switch (kind_) {
    case Kind::lex:
      for (std::size_t i = 0; i < n; ++i) rows.push_back(unit(i, 1));
      break;
    case Kind::deglex:
      if (n == 0) break;
      rows.emplace_back(n, 1);
      for (std::size_t i = 0; i + 1 < n; ++i) rows.push_back(unit(i, 1));
      break;
    case Kind::degrevlex:
      if (n == 0) break;
      rows.emplace_back(n, 1);
      for (std::size_t i = n - 1; i >= 1; --i) rows.push_back(unit(i, -1));
      break;
    case Kind::weighted:
      rows.push_back(weights_);
      for (auto& row : tie_break_.front().matrix(n)) rows.push_back(std::move(row));
      break;
    case Kind::block: {
      std::vector<std::size_t> sizes = block_sizes(blocks_, n);
      std::size_t offset = 0;
      for (std::size_t i = 0; i < blocks_.size(); ++i) {
        for (const auto& sub : blocks_[i].order.matrix(sizes[i])) {
          std::vector<std::int64_t> row(n, 0);
          std::copy(sub.begin(), sub.end(), row.begin() + static_cast<std::ptrdiff_t>(offset));
          rows.push_back(std::move(row));
        }
        offset += sizes[i];
      }
      break;
    }
  }
  return rows;
}

std::string MonomialOrder::describe() const {
  switch (kind_) {
    case Kind::lex:
      return "lex";
    case Kind::deglex:
      return "deglex";
    case Kind::degrevlex:
      return "degrevlex";
    case Kind::weighted: {
      std::string text = "weighted(";
      for (std::size_t i = 0; i < weights_.size(); ++i) {
        if (i) text += ",";
        text += std::to_string(weights_[i]);
      }
      return text + "; " + tie_break_.front().describe() + ")";
    }
    case Kind::block: {
      std::string text = "block(";
      for (std::size_t i = 0; i < blocks_.size(); ++i) {
        if (i) text += ", ";
        text += (blocks_[i].size == 0 ? std::string("rest") : std::to_string(blocks_[i].size)) +
                ": " + blocks_[i].order.describe();
      }
      return text + ")";
    }
  }
  return {};
}

bool operator==(const MonomialOrder& a, const MonomialOrder& b) {
  return a.kind_ == b.kind_ && a.weights_ == b.weights_ && a.tie_break_ == b.tie_break_ &&
         a.blocks_ == b.blocks_;
}

}  // namespace sdfwb::algebra
