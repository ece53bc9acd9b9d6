#include "algebra/gb_poly.h"

namespace sdfwb::algebra::gb {

void IntegerDomain::normalize(std::vector<Coeff>& coeffs) {
  if (coeffs.empty()) return;
  mpz_class g;
  for (const Coeff& c : coeffs) {
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
    if (mpz_cmp_ui(g.get_mpz_t(), 1) == 0) break;
  }
  if (mpz_sgn(coeffs.front().get_mpz_t()) < 0) mpz_neg(g.get_mpz_t(), g.get_mpz_t());
  if (mpz_cmp_ui(g.get_mpz_t(), 1) == 0) return;
  for (Coeff& c : coeffs) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
}

void FmpzDomain::normalize(std::vector<Coeff>& coeffs) {
  if (coeffs.empty()) return;
  Coeff g;
  for (const Coeff& c : coeffs) {
    if (!gcd_above_one(g, c)) break;
  }
  if (fmpz_sgn(coeffs.front().v) < 0) fmpz_neg(g.v, g.v);
  if (is_one(g)) return;
  for (Coeff& c : coeffs) divide_exact(c, g);
}

ModularDomain::Coeff ModularDomain::inverse(Coeff a) const {
  // Extended Euclid on (a, p).
  std::int64_t t = 0, new_t = 1, r = p, new_r = a;
  while (new_r != 0) {
    std::int64_t q = r / new_r;
    std::int64_t tmp = t - q * new_t;
    t = new_t;
    new_t = tmp;
    tmp = r - q * new_r;
    r = new_r;
    new_r = tmp;
  }
  if (t < 0) t += p;
  return static_cast<Coeff>(t);
}

void ModularDomain::normalize(std::vector<Coeff>& coeffs) const {
  if (coeffs.empty() || coeffs.front() == 1) return;
  Coeff inv = inverse(coeffs.front());
  for (Coeff& c : coeffs) mul(c, c, inv);
}

}  // namespace sdfwb::algebra::gb
