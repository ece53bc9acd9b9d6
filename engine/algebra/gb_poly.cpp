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
    if (!gcdAboveOne(g, c)) break;
  }
  if (fmpz_sgn(coeffs.front().v) < 0) fmpz_neg(g.v, g.v);
  if (isOne(g)) return;
  for (Coeff& c : coeffs) divideExact(c, g);
}

ModularDomain::Coeff ModularDomain::inverse(Coeff a) const {
  // Extended Euclid on (a, p).
  std::int64_t t = 0, newT = 1, r = p, newR = a;
  while (newR != 0) {
    std::int64_t q = r / newR;
    std::int64_t tmp = t - q * newT;
    t = newT;
    newT = tmp;
    tmp = r - q * newR;
    r = newR;
    newR = tmp;
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
