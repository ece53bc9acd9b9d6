#pragma once
// The speed-against-error report in Markdown: per scene the Pareto front, the
// scene's default and the cheapest setting within 1/255 of the reference, every
// measured setting, what was not swept and why; a summary over all scenes.

#include <map>
#include <string>

#include "tradeoff/sweep.h"

namespace sdfwb::tradeoff {

struct ReportContext {
    std::string command;                      // how the report was made, quoted at its top
    std::string machine;                      // what it ran on (threads, load, niceness), said after it
    std::map<std::string, std::string> plots; // scene name -> plot path relative to the report
};

std::string writeReport(const SweepResult& result, const ReportContext& context);

}  // namespace sdfwb::tradeoff
