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

MonomialOrder MonomialOrder::lex() { return MonomialOrder(Kind::Lex); }
MonomialOrder MonomialOrder::deglex() { return MonomialOrder(Kind::Deglex); }
MonomialOrder MonomialOrder::degrevlex() { return MonomialOrder(Kind::Degrevlex); }

MonomialOrder MonomialOrder::weighted(std::vector<std::int64_t> weights,
                                      const MonomialOrder& tieBreak) {
  for (std::int64_t w : weights) {
    if (w < 0) throw std::invalid_argument("weighted order: weights must be non-negative");
  }
  MonomialOrder order(Kind::Weighted);
  order.weights_ = std::move(weights);
  order.tieBreak_.push_back(tieBreak);
  return order;
}

MonomialOrder MonomialOrder::block(std::vector<Block> blocks) {
  if (blocks.empty()) throw std::invalid_argument("block order: no blocks");
  MonomialOrder order(Kind::Block);
  order.blocks_ = std::move(blocks);
  return order;
}

MonomialOrder MonomialOrder::elimination(std::size_t eliminated,
                                         const MonomialOrder& eliminatedOrder,
                                         const MonomialOrder& restOrder) {
  // The rest block's size is only known with the ring; 0 here means "all
  // remaining variables" and is resolved by the block's own checks.
  return block({Block{eliminated, eliminatedOrder}, Block{0, restOrder}});
}

std::optional<MonomialOrder> MonomialOrder::fromName(std::string_view name) {
  if (name == "lex") return lex();
  if (name == "deglex") return deglex();
  if (name == "degrevlex") return degrevlex();
  return std::nullopt;
}

namespace {

// Sizes of the blocks for `n` variables; a trailing size 0 takes the rest.
std::vector<std::size_t> blockSizes(const std::vector<MonomialOrder::Block>& blocks,
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

void MonomialOrder::checkFits(std::size_t n) const {
  switch (kind_) {
    case Kind::Lex:
    case Kind::Deglex:
    case Kind::Degrevlex:
      return;
    case Kind::Weighted:
      if (weights_.size() != n) {
        throw std::invalid_argument("weighted order: " + std::to_string(weights_.size()) +
                                    " weights for " + std::to_string(n) + " variables");
      }
      tieBreak_.front().checkFits(n);
      return;
    case Kind::Block: {
      std::vector<std::size_t> sizes = blockSizes(blocks_, n);
      for (std::size_t i = 0; i < blocks_.size(); ++i) blocks_[i].order.checkFits(sizes[i]);
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
    case Kind::Lex:
      for (std::size_t i = 0; i < n; ++i) rows.push_back(unit(i, 1));
      break;
    case Kind::Deglex:
      if (n == 0) break;
      rows.emplace_back(n, 1);
      for (std::size_t i = 0; i + 1 < n; ++i) rows.push_back(unit(i, 1));
      break;
    case Kind::Degrevlex:
      if (n == 0) break;
      rows.emplace_back(n, 1);
      for (std::size_t i = n - 1; i >= 1; --i) rows.push_back(unit(i, -1));
      break;
    case Kind::Weighted:
      rows.push_back(weights_);
      for (auto& row : tieBreak_.front().matrix(n)) rows.push_back(std::move(row));
      break;
    case Kind::Block: {
      std::vector<std::size_t> sizes = blockSizes(blocks_, n);
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
    case Kind::Lex:
      return "lex";
    case Kind::Deglex:
      return "deglex";
    case Kind::Degrevlex:
      return "degrevlex";
    case Kind::Weighted: {
      std::string text = "weighted(";
      for (std::size_t i = 0; i < weights_.size(); ++i) {
        if (i) text += ",";
        text += std::to_string(weights_[i]);
      }
      return text + "; " + tieBreak_.front().describe() + ")";
    }
    case Kind::Block: {
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
  return a.kind_ == b.kind_ && a.weights_ == b.weights_ && a.tieBreak_ == b.tieBreak_ &&
         a.blocks_ == b.blocks_;
}

}  // namespace sdfwb::algebra
