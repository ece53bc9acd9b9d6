#include "algebra/elimination_order.h"

namespace sdfwb::algebra {
namespace {

constexpr EliminationOrderName kEliminationOrders[] = {
    {EliminationOrder::BlockDegrevlex, "elimination",
     "parameters > x, y, z; each block by degrevlex (fastest)"},
    {EliminationOrder::BlockDeglex, "elimination-deglex", "parameters (degrevlex) > x, y, z by deglex"},
    {EliminationOrder::BlockLex, "elimination-lex", "parameters (degrevlex) > x, y, z by lex"},
    {EliminationOrder::Lex, "lex", "lex over parameters > x > y > z (the textbook's; slowest)"},
};

}  // namespace

std::span<const EliminationOrderName> eliminationOrders() { return kEliminationOrders; }

std::optional<EliminationOrder> eliminationOrderFromName(std::string_view name) {
  for (const EliminationOrderName& entry : kEliminationOrders) {
    if (entry.name == name) return entry.order;
  }
  return std::nullopt;
}

}  // namespace sdfwb::algebra
