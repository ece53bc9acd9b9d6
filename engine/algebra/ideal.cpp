#include "algebra/ideal.h"

namespace sdfwb::algebra {

Ideal::Ideal(RingPtr ring, const std::vector<Polynomial>& generators) : ring_(std::move(ring)) {
  generators_.reserve(generators.size());
  for (const Polynomial& g : generators) generators_.push_back(g.inRing(ring_));
}

}  // namespace sdfwb::algebra
