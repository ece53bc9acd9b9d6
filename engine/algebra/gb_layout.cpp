#include "algebra/gb_layout.h"

#include <algorithm>
#include <stdexcept>

namespace sdfwb::algebra::gb {

Layout::Layout(const Ring& ring) : vars_(ring.size()) {
  for (const auto& row : ring.order().matrix(vars_)) {
    std::vector<Word> words;
    for (std::int64_t w : row) {
      if (w > INT32_MAX / 4 || w < INT32_MIN / 4) throw std::invalid_argument("monomial order: weight too large");
      words.push_back(static_cast<Word>(w));
    }
    // Rows that are zero never decide a comparison.
    if (std::any_of(words.begin(), words.end(), [](Word w) { return w != 0; })) matrix_.push_back(std::move(words));
  }
  keys_ = matrix_.size();
  firstRowIsDegree_ =
      keys_ > 0 && std::all_of(matrix_[0].begin(), matrix_[0].end(), [](Word w) { return w >= 0; }) &&
      std::any_of(matrix_[0].begin(), matrix_[0].end(), [](Word w) { return w > 0; });
  stride_ = keys_ + vars_;
  // Spread at most 63 mask bits over the variables: with b bits per
  // variable, bit k says "exponent > k" for k < b, so small exponents are
  // told apart. Variables beyond the 63rd get no bits.
  maskBits_ = vars_ == 0 ? 0 : std::max<std::size_t>(1, 63 / vars_);
  maskVars_ = vars_ == 0 ? 0 : std::min<std::size_t>(vars_, 63 / maskBits_);
}

void Layout::lcm(Word* out, const Word* a, const Word* b) const {
  lcmExponents(out, a, b);
  encodeKeys(out);
}

void Layout::encodeKeys(Word* out) const {
  const Word* e = out + keys_;
  for (std::size_t r = 0; r < keys_; ++r) {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < vars_; ++i) sum += static_cast<std::int64_t>(matrix_[r][i]) * e[i];
    if (sum > INT32_MAX || sum < INT32_MIN) throw std::overflow_error("monomial degree too large");
    out[r] = static_cast<Word>(sum);
  }
}

std::uint64_t Layout::divmask(const Word* m) const {
  // Variable v owns bits [offset, offset + b): the lowest min(e_v, b) are set.
  std::uint64_t mask = 0;
  const Word* e = m + keys_;
  for (std::size_t v = 0; v < maskVars_; ++v) {
    const auto k = static_cast<unsigned>(std::min<Word>(e[v], static_cast<Word>(maskBits_)));
    mask |= ((std::uint64_t{1} << k) - 1) << (v * maskBits_);
  }
  return mask;
}

}  // namespace sdfwb::algebra::gb
