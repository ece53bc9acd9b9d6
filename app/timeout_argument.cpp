#include "app/timeout_argument.h"

#include <cmath>
#include <cstdlib>

#include "io/quoted_text.h"

namespace sdfwb::app {

CLI::Option* addTimeoutOption(CLI::App* command, double& seconds) {
    CLI::Validator positiveOrNone(
        [](std::string& text) -> std::string {
            if (text == "none") {
                text = "0";
                return "";
            }
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !std::isfinite(value) || !(value > 0)) {
                return "must be a positive number of seconds or 'none' (got " + io::quoted(text) + ")";
            }
            return "";
        },
        "SECONDS|none");
    return command->add_option("--timeout", seconds, "Give up after this many seconds ('none': no limit)")
        ->transform(positiveOrNone)
        ->capture_default_str();
}

std::optional<double> timeLimit(double seconds) {
    return seconds > 0 ? std::optional<double>(seconds) : std::nullopt;
}

}  // namespace sdfwb::app
