#include "algebra/rational.h"

namespace sdfwb::algebra {

std::string toString(const Rational& value) {
  // mpq_class keeps its value canonical, so get_str already omits "/1".
  return value.get_str();
}

}  // namespace sdfwb::algebra
