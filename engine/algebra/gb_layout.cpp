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
  first_row_is_degree_ =
      keys_ > 0 && std::all_of(matrix_[0].begin(), matrix_[0].end(), [](Word w) { return w >= 0; }) &&
      std::any_of(matrix_[0].begin(), matrix_[0].end(), [](Word w) { return w > 0; });
  stride_ = keys_ + vars_;
  // Spread 64 mask bits over the variables: with b bits per variable, bit k
  // says "exponent > k" for k < b, so small exponents are told apart.
  const std::size_t bits = vars_ == 0 ? 0 : std::max<std::size_t>(1, 64 / vars_);
  mask_bits_.resize(vars_);
  for (std::size_t v = 0; v < vars_ && v < 64; ++v) {
    for (std::size_t k = 0; k < bits; ++k) mask_bits_[v].push_back(static_cast<std::int32_t>(k));
  }
}

void Layout::lcm(Word* out, const Word* a, const Word* b) const {
  for (std::size_t i = keys_; i < stride_; ++i) out[i] = std::max(a[i], b[i]);
  encode_keys(out);
}

void Layout::encode_keys(Word* out) const {
  const Word* e = out + keys_;
  for (std::size_t r = 0; r < keys_; ++r) {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < vars_; ++i) sum += static_cast<std::int64_t>(matrix_[r][i]) * e[i];
    if (sum > INT32_MAX || sum < INT32_MIN) throw std::overflow_error("monomial degree too large");
    out[r] = static_cast<Word>(sum);
  }
}

std::uint64_t Layout::divmask(const Word* m) const {
  std::uint64_t mask = 0;
  unsigned bit = 0;
  const Word* e = m + keys_;
  for (std::size_t v = 0; v < vars_; ++v) {
    for (std::int32_t threshold : mask_bits_[v]) {
      if (e[v] > threshold) mask |= std::uint64_t{1} << bit;
      ++bit;
    }
  }
  return mask;
}

}  // namespace sdfwb::algebra::gb
