#include "app/algebra_commands.h"

#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "algebra/groebner.h"
#include "app/command_errors.h"
#include "app/timeout_argument.h"
#include "algebra/implicitization.h"
#include "expr/error.h"
#include "expr/identifier.h"
#include "expr/to_algebra.h"
#include "expr/trig.h"

namespace sdfwb::app {
namespace {

// Keeps computations from exhausting the machine: over this they give up.
constexpr std::size_t kMemoryLimitBytes = std::size_t(8) << 30;

algebra::Budget budget(double seconds) {
    algebra::Budget b;
    b.timeLimitSeconds = timeLimit(seconds);
    b.memoryLimitBytes = kMemoryLimitBytes;
    return b;
}

std::vector<std::string> splitVariables(const std::string& text) {
    std::vector<std::string> names;
    std::stringstream in(text);
    std::string name;
    while (std::getline(in, name, ',')) {
        name.erase(0, name.find_first_not_of(" \t"));
        name.erase(name.find_last_not_of(" \t") + 1);
        std::string problem = expr::identifierProblem(name);
        if (!problem.empty()) {
            throw std::invalid_argument("--vars: '" + name + "': " + problem);
        }
        names.push_back(name);
    }
    if (names.empty()) {
        throw std::invalid_argument("--vars: give the variables, e.g. --vars x,y,z");
    }
    return names;
}

// The polynomials as a JSON array of strings in the syntax they are read in.
nlohmann::ordered_json polynomialsJson(const std::vector<algebra::Polynomial>& polynomials) {
    nlohmann::ordered_json array = nlohmann::ordered_json::array();
    for (const algebra::Polynomial& p : polynomials) array.push_back(p.toString());
    return array;
}

}  // namespace

int runImplicitize(const ImplicitizeArguments& a) {
    return runReportingErrors("implicitize", [&] {
        expr::TrigStrategy strategy =
            a.trig == "cos-sin" ? expr::TrigStrategy::CosSinRelation : expr::TrigStrategy::HalfAngle;
        expr::TrigConversion conversion = expr::parseParametrization(a.equations, strategy);
        algebra::ImplicitizationOptions options;
        options.groebner.budget = budget(a.timeout);
        options.order = *algebra::eliminationOrderFromName(a.order);
        algebra::ImplicitizationResult result = algebra::implicitize(conversion.parametrization, options);
        if (!result.ok()) {
            std::cerr << "sdf-workbench implicitize: " << result.message << "\n";
            return kExitGaveUp;
        }
        if (a.json) {
            nlohmann::ordered_json out = {{"generators", polynomialsJson(result.generators)},
                                          {"degree", result.degree()},
                                          {"terms", result.termCount()},
                                          {"method", result.method},
                                          {"seconds", result.seconds}};
            std::cout << out.dump() << "\n";
            return 0;
        }
        if (result.generators.empty()) {
            std::cout << "no equation: the image is dense (the elimination ideal is zero)\n";
        } else if (result.generators.size() == 1) {
            std::cout << result.generators[0].toString() << " = 0\n";
        } else {
            std::cout << "the elimination ideal has " << result.generators.size()
                      << " generators; the variety is where all vanish:\n";
            for (const algebra::Polynomial& g : result.generators) std::cout << g.toString() << " = 0\n";
        }
        std::cout << "degree " << result.degree() << ", " << result.termCount() << " terms, " << result.seconds
                  << " s by " << result.method << "\n";
        return 0;
    });
}

int runGroebner(const GroebnerArguments& a) {
    return runReportingErrors("groebner", [&] {
        std::vector<std::string> variables = splitVariables(a.vars);
        algebra::RingPtr ring = algebra::Ring::make(variables, *algebra::MonomialOrder::fromName(a.order));
        std::vector<algebra::Polynomial> polynomials = expr::parsePolynomials(a.polynomials, ring);
        algebra::GroebnerOptions options;
        options.budget = budget(a.timeout);
        algebra::GroebnerResult result = algebra::groebnerBasis(algebra::Ideal(ring, polynomials), options);
        if (!result.ok()) {
            std::cerr << "sdf-workbench groebner: " << result.message << "\n";
            return kExitGaveUp;
        }
        if (a.json) {
            nlohmann::ordered_json out = {{"basis", polynomialsJson(result.basis)}, {"seconds", result.seconds}};
            std::cout << out.dump() << "\n";
            return 0;
        }
        for (const algebra::Polynomial& g : result.basis) std::cout << g.toString() << "\n";
        std::cout << result.basis.size() << " polynomials, " << result.seconds << " s\n";
        return 0;
    });
}

}  // namespace sdfwb::app
