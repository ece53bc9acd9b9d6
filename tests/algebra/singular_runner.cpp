#include "singular_runner.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sdfwb::algebra::testing {

namespace {

std::string orderName(const MonomialOrder& order, std::size_t size) {
  switch (order.kind()) {
    case MonomialOrder::Kind::Lex: return size ? "lp(" + std::to_string(size) + ")" : "lp";
    case MonomialOrder::Kind::Deglex: return size ? "Dp(" + std::to_string(size) + ")" : "Dp";
    case MonomialOrder::Kind::Degrevlex: return size ? "dp(" + std::to_string(size) + ")" : "dp";
    default: return {};
  }
}

// The ring's polynomials with variables renamed to Singular-safe names.
RingPtr renamed(const Ring& ring, const std::vector<std::string>& names) {
  return Ring::make(names, ring.order());
}

std::string asSingular(const Polynomial& p, const RingPtr& renamedRing) {
  return Polynomial(renamedRing, p.terms()).toString();
}

std::string run(const std::string& script, double timeoutSeconds, std::string& error) {
  std::optional<std::string> exe = singularPath();
  if (!exe) {
    error = "Singular is not installed";
    return {};
  }
  std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("sdfwb-singular-" + std::to_string(::getpid()) + ".sing");
  {
    std::ofstream out(file);
    out << script;
  }
  std::string command = "timeout -s KILL " + std::to_string(static_cast<int>(timeoutSeconds + 1)) + " " + *exe +
                        " -q --no-rc --no-warn " + file.string() + " 2>&1";
  std::string output;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    std::array<char, 4096> buffer;
    std::size_t n;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) output.append(buffer.data(), n);
    int status = ::pclose(pipe);
    if (status != 0) error = "Singular exited with status " + std::to_string(status) + " (timeout?)";
  } else {
    error = "cannot start Singular";
  }
  std::filesystem::remove(file);
  return output;
}

std::vector<std::string> varNames(const char* prefix, std::size_t n) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < n; ++i) names.push_back(prefix + std::to_string(i));
  return names;
}

// Singular's CPU timer counts in steps of 10 ms: a command is repeated until
// it has run 100 ms of CPU (at most 1000 times), and the times divided by
// the repetitions. kRepeatUntil opens the loop; the script closes it with
// "reps++; }" and prints "TIME <wall ms> <cpu ms> <repetitions>".
constexpr const char* kRepeatUntil =
    "int t = rtimer;\nint c = timer;\nint reps = 0;\n"
    "while (reps == 0 || (timer - c < 100 && reps < 1000)) {\n";
constexpr const char* kPrintTime =
    "print(\"TIME \" + string(rtimer - t) + \" \" + string(timer - c) + \" \" + string(reps));\n";

// Reads "TIME <wall ms> <cpu ms> <repetitions>" and the lines between BEGIN and END.
SingularResult readOutput(const std::string& output, const RingPtr& ring, const char* prefix,
                           std::string error) {
  SingularResult result;
  std::istringstream in(output);
  std::string line;
  bool inside = false;
  bool done = false;
  try {
    while (std::getline(in, line)) {
      if (line.rfind("TIME ", 0) == 0) {
        std::istringstream times(line.substr(5));
        double wallMs = 0, cpuMs = 0, repetitions = 1;
        times >> wallMs >> cpuMs >> repetitions;
        result.seconds = wallMs / 1000.0 / repetitions;
        result.cpuSeconds = cpuMs / 1000.0 / repetitions;
      } else if (line == "BEGIN") {
        inside = true;
      } else if (line == "END") {
        done = true;
        inside = false;
      } else if (inside && !line.empty()) {
        Polynomial p = parseSingularPolynomial(line, ring, prefix);
        if (!p.isZero()) result.basis.push_back(p.monic());
      }
    }
  } catch (const std::exception& e) {
    error = std::string("cannot read Singular's output: ") + e.what();
  }
  if (!done && error.empty()) error = "unexpected Singular output: " + output.substr(0, 300);
  std::sort(result.basis.begin(), result.basis.end(), [&](const Polynomial& a, const Polynomial& b) {
    return ring->compare(a.leadingMonomial(), b.leadingMonomial()) < 0;
  });
  result.ok = error.empty();
  result.error = error;
  return result;
}

const char* kPrintBasis =
    "print(\"BEGIN\");\n"
    "for (int k = 1; k <= size(g); k++) { print(string(g[k])); }\n"
    "print(\"END\");\n";

}  // namespace

std::optional<std::string> singularPath() {
  for (const char* candidate : {"/usr/bin/Singular", "/usr/local/bin/Singular"}) {
    if (::access(candidate, X_OK) == 0) return std::string(candidate);
  }
  return std::nullopt;
}

std::optional<std::string> singularOrder(const Ring& ring) {
  const MonomialOrder& order = ring.order();
  switch (order.kind()) {
    case MonomialOrder::Kind::Lex:
    case MonomialOrder::Kind::Deglex:
    case MonomialOrder::Kind::Degrevlex:
      return orderName(order, 0);
    case MonomialOrder::Kind::Weighted: {
      // Our weighted order is "weights, then the tie-break order", which is
      // Singular's extra weight vector a(w) followed by the tie-break.
      std::string tie = orderName(order.tieBreak(), 0);
      if (tie.empty()) return std::nullopt;
      std::string weights;
      for (std::int64_t w : order.weights()) weights += (weights.empty() ? "" : ",") + std::to_string(w);
      return "(a(" + weights + ")," + tie + ")";
    }
    case MonomialOrder::Kind::Block: {
      std::string text = "(";
      std::size_t used = 0;
      for (std::size_t i = 0; i < order.blocks().size(); ++i) {
        std::size_t size = order.blocks()[i].size;
        if (size == 0) size = ring.size() - used;
        used += size;
        std::string part = orderName(order.blocks()[i].order, size);
        if (part.empty()) return std::nullopt;
        text += (i ? "," : "") + part;
      }
      return text + ")";
    }
  }
  return std::nullopt;
}

Polynomial parseSingularPolynomial(const std::string& text, const RingPtr& ring, const char* prefix) {
  std::vector<Term> terms;
  std::size_t pos = 0;
  const std::string p = prefix;
  auto fail = [&](const std::string& what) {
    throw std::runtime_error(what + " at column " + std::to_string(pos + 1) + " of '" + text + "'");
  };
  auto readNumber = [&]() {
    std::size_t start = pos;
    while (pos < text.size() && (std::isdigit(static_cast<unsigned char>(text[pos])) || text[pos] == '/')) ++pos;
    if (start == pos) fail("number expected");
    Rational value(text.substr(start, pos - start));
    value.canonicalize();
    return value;
  };
  while (pos < text.size()) {
    int sign = 1;
    if (text[pos] == '+' || text[pos] == '-') {
      sign = text[pos] == '-' ? -1 : 1;
      ++pos;
    } else if (!terms.empty()) {
      fail("'+' or '-' expected");
    }
    Term term{ring->oneMonomial(), Rational(sign)};
    for (;;) {
      if (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) {
        term.coefficient *= readNumber();
      } else if (text.compare(pos, p.size(), p) == 0) {
        pos += p.size();
        std::size_t start = pos;
        while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) ++pos;
        if (start == pos) fail("variable index expected");
        std::size_t index = std::stoul(text.substr(start, pos - start));
        if (index >= ring->size()) fail("unknown variable");
        Exponent e = 1;
        if (pos < text.size() && text[pos] == '^') {
          ++pos;
          start = pos;
          while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) ++pos;
          if (start == pos) fail("exponent expected");
          e = static_cast<Exponent>(std::stoul(text.substr(start, pos - start)));
        }
        term.monomial[index] += e;
      } else {
        fail("number or variable expected");
      }
      if (pos < text.size() && text[pos] == '*') {
        ++pos;
        continue;
      }
      break;
    }
    terms.push_back(std::move(term));
  }
  return Polynomial(ring, std::move(terms));
}

SingularResult singularStd(const Ideal& ideal, double timeoutSeconds, const std::string& command) {
  const Ring& ring = *ideal.ring();
  std::optional<std::string> order = singularOrder(ring);
  if (!order) return SingularResult{false, "no Singular name for order " + ring.order().describe(), {}, 0};
  std::vector<std::string> names = varNames("v", ring.size());
  RingPtr named = renamed(ring, names);
  std::string script = "ring r = 0, (";
  for (std::size_t i = 0; i < names.size(); ++i) script += (i ? "," : "") + names[i];
  script += "), " + *order + ";\nshort = 0;\noption(redSB);\nsystem(\"--ticks-per-sec\", 1000);\nideal i = ";
  for (std::size_t k = 0; k < ideal.generators().size(); ++k) {
    script += (k ? ",\n  " : "") + asSingular(ideal.generators()[k], named);
  }
  if (ideal.generators().empty()) script += "0";
  script += ";\nideal g;\n";
  script += kRepeatUntil;
  script += "  g = " + command + "(i);\n  reps++;\n}\n";
  script += kPrintTime;
  script += kPrintBasis;
  script += "quit;\n";
  std::string error;
  std::string output = run(script, timeoutSeconds, error);
  return readOutput(output, ideal.ring(), "v", error);
}

SingularResult singularEliminate(const Ideal& ideal, const std::vector<std::string>& eliminated,
                                  const RingPtr& target, double timeoutSeconds) {
  const Ring& ring = *ideal.ring();
  // Remaining variables are named after their index in `target` (w0, w1...),
  // eliminated ones e0, e1, ...
  std::vector<std::string> names;
  std::string product;
  std::size_t e = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const std::string& v = ring.variable(i);
    if (std::find(eliminated.begin(), eliminated.end(), v) != eliminated.end()) {
      names.push_back("e" + std::to_string(e++));
      product += (product.empty() ? "" : "*") + names.back();
    } else {
      std::optional<std::size_t> j = target->indexOf(v);
      if (!j) return SingularResult{false, "variable " + v + " is missing from the target ring", {}, 0};
      names.push_back("w" + std::to_string(*j));
    }
  }
  std::optional<std::string> targetOrder = singularOrder(*target);
  if (!targetOrder) return SingularResult{false, "no Singular name for the target order", {}, 0};
  RingPtr named = Ring::make(names, MonomialOrder::degrevlex());
  std::string script = "ring r = 0, (";
  for (std::size_t i = 0; i < names.size(); ++i) script += (i ? "," : "") + names[i];
  script += "), dp;\nshort = 0;\nsystem(\"--ticks-per-sec\", 1000);\nideal i = ";
  for (std::size_t k = 0; k < ideal.generators().size(); ++k) {
    script += (k ? ",\n  " : "") + Polynomial(named, ideal.generators()[k].terms()).toString();
  }
  script += ";\nideal el;\nring s = 0, (";
  for (std::size_t j = 0; j < target->size(); ++j) script += (j ? "," : "") + std::string("w") + std::to_string(j);
  script += "), " + *targetOrder + ";\nshort = 0;\noption(redSB);\nideal g;\n";
  script += kRepeatUntil;
  script += "  setring r;\n  el = eliminate(i, " + product + ");\n  setring s;\n  g = std(imap(r, el));\n  reps++;\n}\n";
  script += kPrintTime;
  script += kPrintBasis;
  script += "quit;\n";
  std::string error;
  std::string output = run(script, timeoutSeconds, error);
  return readOutput(output, target, "w", error);
}

}  // namespace sdfwb::algebra::testing
