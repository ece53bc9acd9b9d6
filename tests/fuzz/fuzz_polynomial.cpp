// Fuzz target: polynomials as groebner reads them. Text either converts to
// exact polynomials over x, y, z or fails with one exception; no input
// crashes, wraps an exponent or expands without bound.

#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "expr/error.h"
#include "expr/to_algebra.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sdfwb;
    static const algebra::RingPtr ring = algebra::Ring::make({"x", "y", "z"});
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        for (const algebra::Polynomial& p : expr::parsePolynomials(text, ring)) p.toString();
    } catch (const expr::Error&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
