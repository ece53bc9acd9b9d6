#pragma once
// `sdf-workbench tradeoff`: what each quality setting costs and what it buys,
// measured against a reference (engine/tradeoff), as a Markdown report with plots.

#include "app/tradeoff_arguments.h"

namespace sdfwb::app {

// 0 when the report was written, 130 when interrupted (no report), 2 on bad input, 1 on other errors.
int runTradeoff(const TradeoffArguments& arguments);

}  // namespace sdfwb::app
