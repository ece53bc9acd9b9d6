#include "algebra/division_image.h"

#include <flint/nmod_poly.h>
#include <flint/ulong_extras.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace sdfwb::algebra {
namespace {

constexpr ulong kPrime = (ulong(1) << 61) - 1;  // a Mersenne prime: the images hardly ever degenerate

// Fixed substitution values, so that a refusal replays.
ulong substitutionValue(std::size_t variable) { return (0x9E3779B97F4A7C15ull * (variable + 1)) % kPrime; }

std::optional<ulong> modPrime(const Rational& value) {
    ulong numerator = mpz_fdiv_ui(value.get_num_mpz_t(), kPrime);
    ulong denominator = mpz_fdiv_ui(value.get_den_mpz_t(), kPrime);
    if (denominator == 0) return std::nullopt;
    return n_mulmod2(numerator, n_invmod(denominator, kPrime), kPrime);
}

// p's image in F_prime[x_main] with every other variable substituted.
class UnivariateImage {
public:
    UnivariateImage() { nmod_poly_init(poly_, kPrime); }
    ~UnivariateImage() { nmod_poly_clear(poly_); }
    UnivariateImage(const UnivariateImage&) = delete;
    UnivariateImage& operator=(const UnivariateImage&) = delete;

    bool set(const Polynomial& p, std::size_t main) {
        std::vector<ulong> coefficients(p.degreeIn(main) + std::size_t(1), 0);
        for (const Term& term : p.terms()) {
            std::optional<ulong> c = modPrime(term.coefficient);
            if (!c) return false;
            const std::vector<Exponent>& exponents = term.monomial.exponents();
            for (std::size_t v = 0; v < exponents.size(); ++v) {
                if (v != main && exponents[v] != 0) {
                    *c = n_mulmod2(*c, n_powmod2(substitutionValue(v), exponents[v], kPrime), kPrime);
                }
            }
            ulong& slot = coefficients[exponents[main]];
            slot = n_addmod(slot, *c, kPrime);
        }
        for (std::size_t k = 0; k < coefficients.size(); ++k) {
            if (coefficients[k] != 0) nmod_poly_set_coeff_ui(poly_, static_cast<slong>(k), coefficients[k]);
        }
        return true;
    }
    nmod_poly_struct* get() { return poly_; }

private:
    nmod_poly_t poly_;
};

}  // namespace

bool imageRefutesDivision(const Polynomial& f, const Polynomial& g) {
    // the variable g has most of, so its image keeps as much of g as it can
    std::size_t main = 0;
    for (std::size_t v = 1; v < g.ring()->size(); ++v) {
        if (g.degreeIn(v) > g.degreeIn(main)) main = v;
    }
    if (g.degreeIn(main) == 0) return false;
    UnivariateImage fImage, gImage;
    if (!fImage.set(f, main) || !gImage.set(g, main) || nmod_poly_is_zero(gImage.get())) return false;
    UnivariateImage remainder;
    nmod_poly_rem(remainder.get(), fImage.get(), gImage.get());
    return !nmod_poly_is_zero(remainder.get());
}

}  // namespace sdfwb::algebra
