#pragma once
// One convention for how every subcommand ends (README "Exit status"):
//   0 done, 1 a check did not pass (compare, parity), 2 an error of any kind
//   (arguments, scene, formula, a file that cannot be read or written, not
//   enough memory), 3 an algebra computation gave up (time or memory limit);
//   a termination signal ends the process with its conventional status.

#include <functional>

namespace sdfwb::app {

inline constexpr int kExitCheckFailed = 1;
inline constexpr int kExitError = 2;
inline constexpr int kExitGaveUp = 3;

// Runs `body` (which returns the exit status) and turns any exception into
// one line per problem on stderr, "sdf-workbench <command>: <problem>", and kExitError.
int runReportingErrors(const char* command, const std::function<int()>& body);

}  // namespace sdfwb::app
