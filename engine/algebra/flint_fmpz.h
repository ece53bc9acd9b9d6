#pragma once
// An owning FLINT integer (fmpz): one word for values below 2^62, a GMP
// integer from FLINT's cache above, so small values cost no allocation.

#include <flint/fmpz.h>

namespace sdfwb::algebra {

struct Fmpz {
  fmpz_t v;
  Fmpz() { fmpz_init(v); }
  explicit Fmpz(slong value) { fmpz_init_set_si(v, value); }
  Fmpz(const Fmpz& other) { fmpz_init_set(v, other.v); }
  // An fmpz is one word (a value or a tagged pointer): moving copies it.
  Fmpz(Fmpz&& other) noexcept {
    *v = *other.v;
    fmpz_init(other.v);
  }
  Fmpz& operator=(const Fmpz& other) {
    fmpz_set(v, other.v);
    return *this;
  }
  Fmpz& operator=(Fmpz&& other) noexcept {
    fmpz_swap(v, other.v);
    return *this;
  }
  ~Fmpz() { fmpz_clear(v); }
};

}  // namespace sdfwb::algebra
