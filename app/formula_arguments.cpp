#include "app/formula_arguments.h"

#include <algorithm>

namespace sdfwb::app {
namespace {

bool looksLikeFormula(const std::string& argument) {
    const std::string name = argument.substr(0, argument.find('='));
    return argument.size() > 1 && argument[0] == '-' && argument != "--" &&
           name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") !=
               std::string::npos;
}

}  // namespace

std::vector<std::string> formulasAsPositionals(std::vector<std::string> arguments, const CLI::App& app,
                                               const std::vector<std::string>& formulaCommands) {
    auto command = std::find_if(arguments.begin(), arguments.end(), [&](const std::string& a) {
        return std::find(formulaCommands.begin(), formulaCommands.end(), a) != formulaCommands.end();
    });
    if (command == arguments.end()) {
        return arguments;
    }
    const CLI::App* sub = app.get_subcommand(*command);
    std::vector<std::string> kept(arguments.begin(), command + 1), formulas;
    auto it = command + 1;
    for (; it != arguments.end() && *it != "--"; ++it) {
        if (looksLikeFormula(*it) && sub->get_option_no_throw(it->substr(0, it->find('='))) == nullptr) {
            formulas.push_back(*it);
        } else {
            kept.push_back(*it);
        }
    }
    if (formulas.empty()) {
        return arguments;
    }
    kept.push_back("--");
    kept.insert(kept.end(), formulas.begin(), formulas.end());
    if (it != arguments.end()) {
        kept.insert(kept.end(), it + 1, arguments.end());
    }
    return kept;
}

}  // namespace sdfwb::app
