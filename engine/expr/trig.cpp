#include "expr/trig.h"

#include <map>
#include <optional>

#include "algebra/ring.h"
#include "expr/graph_to_fractions.h"

namespace sdfwb::expr {
namespace {

using algebra::Polynomial;

bool isTrig(Op op) { return op == Op::Sin || op == Op::Cos || op == Op::Tan; }

// constant + sum(coefficients[v] * variable v)
struct LinearForm {
  mpq_class constant;
  std::map<std::uint32_t, mpq_class> coefficients;

  bool isConstant() const { return coefficients.empty(); }
  LinearForm scaled(const mpq_class& factor) const {
    LinearForm r{constant * factor, {}};
    if (factor != 0) {
      for (const auto& [v, c] : coefficients) r.coefficients[v] = c * factor;
    }
    return r;
  }
  LinearForm plus(const LinearForm& other) const {
    LinearForm r = *this;
    r.constant += other.constant;
    for (const auto& [v, c] : other.coefficients) {
      r.coefficients[v] += c;
      if (r.coefficients[v] == 0) r.coefficients.erase(v);
    }
    return r;
  }
};

// The argument as a linear form in the graph variables, if it is one.
std::optional<LinearForm> linearForm(const Graph& g, NodeId root) {
  std::map<NodeId, std::optional<LinearForm>> forms;
  for (const NodeId id : dependencies(g, root)) {
    const Node& n = g.node(id);
    auto arg = [&](int i) -> const std::optional<LinearForm>& { return forms[n.args[i]]; };
    std::optional<LinearForm> f;
    switch (n.op) {
      case Op::Constant: f = LinearForm{g.exactValue(id), {}}; break;
      case Op::Variable: f = LinearForm{0, {{n.index, 1}}}; break;
      case Op::Neg:
        if (arg(0)) f = arg(0)->scaled(-1);
        break;
      case Op::Add:
        if (arg(0) && arg(1)) f = arg(0)->plus(*arg(1));
        break;
      case Op::Sub:
        if (arg(0) && arg(1)) f = arg(0)->plus(arg(1)->scaled(-1));
        break;
      case Op::Mul:
        if (arg(0) && arg(1) && arg(0)->isConstant()) f = arg(1)->scaled(arg(0)->constant);
        else if (arg(0) && arg(1) && arg(1)->isConstant()) f = arg(0)->scaled(arg(1)->constant);
        break;
      case Op::Div:
        if (arg(0) && arg(1) && arg(1)->isConstant() && arg(1)->constant != 0) {
          f = arg(0)->scaled(1 / arg(1)->constant);
        }
        break;
      default: break;
    }
    forms[id] = std::move(f);
  }
  return forms[root];
}

struct Complex {
  Polynomial re, im;
};

Complex multiply(const Complex& a, const Complex& b) {
  return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}

Complex power(Complex base, unsigned long n, const algebra::RingPtr& ring) {
  Complex result{ring->one(), ring->zero()};
  while (n > 0) {
    if (n & 1ul) result = multiply(result, base);
    n >>= 1;
    if (n > 0) base = multiply(base, base);
  }
  return result;
}

// One parameter that occurs inside sin/cos/tan.
struct Angle {
  std::uint32_t variable;
  mpq_class scale;
  Complex unit;                      // cos psi + i sin psi, times (1 + t^2) for HalfAngle
  std::optional<Fraction> unitScale; // 1/(1 + t^2) for HalfAngle
};

}  // namespace

TrigConversion toRationalParametrization(const ParametricEquations& equations, TrigStrategy strategy) {
  const Graph& g = equations.graph;

  // The trigonometric nodes and the linear forms of their arguments.
  std::map<NodeId, LinearForm> trigArguments;
  for (const CoordinateEquation& e : equations.equations) {
    for (const NodeId id : dependencies(g, e.value, [&](NodeId n) { return isTrig(g.node(n).op); })) {
      if (!isTrig(g.node(id).op) || trigArguments.count(id)) continue;
      const std::optional<LinearForm> form = linearForm(g, g.node(id).args[0]);
      if (!form || form->constant != 0) {
        throw Error(g.origin(id).where, "the argument of '" + std::string(opInfo(g.node(id).op).name) +
                                            "' must be a rational multiple of parameters, such as 2*v or v/2");
      }
      trigArguments.emplace(id, *form);
    }
  }

  // Each angle's scale m (parameter = m*psi): the lcm of the coefficients'
  // denominators over the gcd of their numerators, so each coefficient times m
  // is an integer and these integers are coprime.
  std::map<std::uint32_t, mpq_class> scales;
  for (const auto& [id, form] : trigArguments) {
    for (const auto& [v, c] : form.coefficients) {
      auto [it, fresh] = scales.emplace(v, abs(c));
      if (!fresh) {
        mpz_class num, den;
        mpz_gcd(num.get_mpz_t(), it->second.get_num_mpz_t(), c.get_num_mpz_t());
        mpz_lcm(den.get_mpz_t(), it->second.get_den_mpz_t(), c.get_den_mpz_t());
        it->second = mpq_class(num, den);
        it->second.canonicalize();
      }
    }
  }
  for (auto& [v, gcdOverLcm] : scales) gcdOverLcm = 1 / gcdOverLcm;

  // The ring: user parameters in order, each angle replaced by its new parameters.
  TrigConversion conversion;
  algebra::RationalParametrization& result = conversion.parametrization;
  std::vector<std::string> taken = g.variables();
  taken.insert(taken.end(), {"x", "y", "z"});
  std::vector<std::vector<std::string>> replacements(g.variables().size());
  for (std::uint32_t v = 0; v < g.variables().size(); ++v) {
    const std::string& name = g.variables()[v];
    if (!scales.count(v)) {
      result.parameters.push_back(name);
      continue;
    }
    const std::vector<std::string> hints =
        strategy == TrigStrategy::HalfAngle ? std::vector<std::string>{"t_" + name}
                                            : std::vector<std::string>{"c_" + name, "s_" + name};
    for (const std::string& hint : hints) {
      replacements[v].push_back(algebra::internalVariableName(hint, taken));
      taken.push_back(replacements[v].back());
      result.parameters.push_back(replacements[v].back());
    }
    conversion.angles.push_back({name, scales[v], replacements[v]});
  }
  const algebra::RingPtr ring = algebra::Ring::make(result.parameters);
  FractionArithmetic arithmetic(ring);

  std::map<std::uint32_t, Angle> angles;
  for (const auto& [v, scale] : scales) {
    Angle angle{v, scale, {ring->zero(), ring->zero()}, std::nullopt};
    if (strategy == TrigStrategy::HalfAngle) {
      const Polynomial t = ring->var(replacements[v][0]);
      angle.unit = {1 - t * t, 2 * t};
      angle.unitScale = arithmetic.quotient(ring->one(), 1 + t * t);
    } else {
      const Polynomial c = ring->var(replacements[v][0]), s = ring->var(replacements[v][1]);
      angle.unit = {c, s};
      result.relations.push_back(c * c + s * s - 1);
    }
    angles.emplace(v, std::move(angle));
  }

  // cos + i sin of each argument: the product of the angles' units to their multiples.
  std::map<NodeId, Fraction> trigValues;
  for (const auto& [id, form] : trigArguments) try {
    Complex value{ring->one(), ring->zero()};
    Fraction scale = arithmetic.constant(1);
    for (const auto& [v, c] : form.coefficients) {
      const Angle& angle = angles.at(v);
      const mpq_class multiple = c * angle.scale;  // an integer by the choice of scale
      if (abs(multiple.get_num()) > kMaxAngleMultiple) {
        throw Error(g.origin(id).where, "the multiples of '" + g.variables()[v] +
                                            "' are too far apart for an exact conversion (at most " +
                                            std::to_string(kMaxAngleMultiple) + " times the smallest)");
      }
      const unsigned long magnitude = mpz_class(abs(multiple.get_num())).get_ui();
      Complex unit = angle.unit;
      if (multiple < 0) unit.im = -unit.im;  // e^(-i n psi) is the conjugate of e^(i n psi)
      value = multiply(value, power(unit, magnitude, ring));
      if (angle.unitScale) {
        for (unsigned long k = 0; k < magnitude; ++k) scale = arithmetic.multiply(scale, *angle.unitScale);
      }
    }
    const Fraction cosine = arithmetic.multiply(arithmetic.polynomial(value.re), scale);
    const Fraction sine = arithmetic.multiply(arithmetic.polynomial(value.im), scale);
    switch (g.node(id).op) {
      case Op::Cos: trigValues.emplace(id, cosine); break;
      case Op::Sin: trigValues.emplace(id, sine); break;
      default: {
        auto tangent = arithmetic.divide(sine, cosine);
        trigValues.emplace(id, std::move(*tangent));  // cos(n psi) is never identically 0
      }
    }
  } catch (const TooLargeToExpand& error) {
    throw Error(g.origin(id).where, error.what());
  }

  GraphToFractions::Options options;
  for (std::uint32_t v = 0; v < g.variables().size(); ++v) {
    options.variables.push_back(scales.count(v) ? std::nullopt : std::optional(ring->var(g.variables()[v])));
  }
  options.unmappedVariable = [](const std::string& name) {
    return "'" + name + "' is used both inside and outside sin/cos/tan, so the parametrization is not rational";
  };
  options.isLeaf = [&](NodeId id) { return isTrig(g.node(id).op); };
  options.leaf = [&](NodeId id) { return trigValues.at(id); };
  GraphToFractions converter(g, arithmetic, std::move(options));
  for (const CoordinateEquation& e : equations.equations) {
    auto [numerator, denominator] = converter.convertToQuotient(e.value, e.where);
    result.coordinates.push_back(e.coordinate);
    result.numerators.push_back(std::move(numerator));
    result.denominators.push_back(std::move(denominator));
  }
  return conversion;
}

TrigConversion parseParametrization(std::string_view source, TrigStrategy strategy) {
  return toRationalParametrization(compileParametricEquations(source), strategy);
}

}  // namespace sdfwb::expr
