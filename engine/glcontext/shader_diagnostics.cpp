#include "glcontext/shader_diagnostics.h"

#include <cctype>
#include <optional>
#include <regex>

namespace sdfwb::glcontext {

namespace {

// One pattern per driver family, with the regex groups holding each part
// (0: the format lacks that part).
struct LogPattern {
  std::regex regex;
  int lineGroup;
  int columnGroup;
  int severityGroup;  // a severity written before the location, "ERROR: 0:12: ..."
  int messageGroup;
};

const std::vector<LogPattern>& logPatterns() {
  static const std::vector<LogPattern> patterns = {
      {std::regex(R"(^\d+:(\d+)\((\d+)\): (.*)$)"), 1, 2, 0, 3},           // Mesa
      {std::regex(R"(^\d+\((\d+)\) ?: (.*)$)"), 1, 0, 0, 2},               // NVIDIA
      {std::regex(R"(^(ERROR|WARNING): \d+:(\d+): (.*)$)"), 2, 0, 1, 3},    // AMD, Intel, ANGLE
  };
  return patterns;
}

std::optional<ShaderDiagnostic> parseLocated(const std::string& text) {
  std::smatch match;
  for (const LogPattern& pattern : logPatterns()) {
    if (!std::regex_match(text, match, pattern.regex)) continue;
    ShaderDiagnostic diagnostic;
    diagnostic.line = std::stoi(match[pattern.lineGroup]);
    if (pattern.columnGroup) diagnostic.column = std::stoi(match[pattern.columnGroup]);
    diagnostic.message = match[pattern.messageGroup];
    if (pattern.severityGroup) {
      // "ERROR: 0:12: msg" -> "error: msg", as Mesa would print it.
      std::string severity = match[pattern.severityGroup];
      for (char& c : severity) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      diagnostic.message = severity + ": " + diagnostic.message;
    }
    return diagnostic;
  }
  return std::nullopt;
}

// Line `line` (from 1) of `source`, if it has that many lines.
std::optional<std::string_view> sourceLine(std::string_view source, int line) {
  for (int current = 1; current < line; ++current) {
    std::size_t newline = source.find('\n');
    if (newline == std::string_view::npos) return std::nullopt;
    source.remove_prefix(newline + 1);
  }
  return source.substr(0, source.find('\n'));
}

// Mesa counts columns (from 1) in the preprocessed text, where each run of
// whitespace and comments has become one space; walk the original line the
// same way to find the character the column means. npos if out of range.
std::size_t originalIndex(std::string_view text, int column) {
  int collapsed = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t start = i;
    bool gap = false;
    while (i < text.size()) {
      if (std::isspace(static_cast<unsigned char>(text[i]))) {
        ++i;
      } else if (text.substr(i, 2) == "/*") {
        std::size_t end = text.find("*/", i + 2);
        i = end == std::string_view::npos ? text.size() : end + 2;
      } else if (text.substr(i, 2) == "//") {
        i = text.size();
      } else {
        break;
      }
      gap = true;
    }
    if (gap) {
      if (++collapsed == column) return start;
      continue;
    }
    if (++collapsed == column) return i;
    ++i;
  }
  return std::string_view::npos;
}

}  // namespace

std::vector<ShaderDiagnostic> parseInfoLog(std::string_view log, GLenum stage) {
  std::vector<ShaderDiagnostic> diagnostics;
  while (!log.empty()) {
    std::size_t newline = log.find('\n');
    std::string text(log.substr(0, newline));
    log.remove_prefix(newline == std::string_view::npos ? log.size() : newline + 1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    if (text.empty()) continue;
    ShaderDiagnostic diagnostic = parseLocated(text).value_or(ShaderDiagnostic{0, 0, 0, text});
    diagnostic.stage = stage;
    diagnostics.push_back(std::move(diagnostic));
  }
  return diagnostics;
}

std::string formatDiagnostics(std::string_view what, std::string_view source,
                              const std::vector<ShaderDiagnostic>& diagnostics) {
  std::string out;
  int echoedLine = 0;
  for (const ShaderDiagnostic& diagnostic : diagnostics) {
    out += what;
    if (diagnostic.line > 0) {
      out += ":" + std::to_string(diagnostic.line);
      if (diagnostic.column > 0) out += ":" + std::to_string(diagnostic.column);
    }
    out += ": " + diagnostic.message + "\n";
    // Mesa reports one mistake as several messages on the same line, inner
    // expression first: echo the line once, under the first of them.
    if (diagnostic.line <= 0 || diagnostic.line == echoedLine) continue;
    echoedLine = diagnostic.line;
    std::optional<std::string_view> line = sourceLine(source, diagnostic.line);
    if (!line) continue;
    std::string_view text = *line;
    std::string number = std::to_string(diagnostic.line);
    std::string gutter = std::string(number.size() < 5 ? 5 - number.size() : 0, ' ') + number + " | ";
    out += gutter + std::string(text) + "\n";
    if (diagnostic.column <= 0) continue;
    std::size_t index = originalIndex(text, diagnostic.column);
    if (index == std::string_view::npos) continue;
    std::string pad(gutter.size() - 2, ' ');
    // Keep tabs so the caret lines up under tab-indented source.
    std::string indent(text.substr(0, index));
    for (char& c : indent) {
      if (c != '\t') c = ' ';
    }
    out += pad + "| " + indent + "^\n";
  }
  return out;
}

}  // namespace sdfwb::glcontext
