# Writes OUTPUT: a C++ source defining `std::string_view <FUNCTION>()` that returns
# the concatenation of INPUTS (a ;-separated list) as a raw string literal.
set(content "")
foreach(input ${INPUTS})
  file(READ ${input} text)
  string(APPEND content "${text}")
endforeach()
set(delimiter "SDFWB_EMBED")
file(WRITE ${OUTPUT}.tmp
  "// Generated from ${INPUTS} by embed_text.cmake; do not edit.\n"
  "#include <string_view>\n"
  "namespace ${NAMESPACE} {\n"
  "std::string_view ${FUNCTION}() {\n"
  "    static constexpr char text[] = R\"${delimiter}(${content})${delimiter}\";\n"
  "    return {text, sizeof(text) - 1};\n"
  "}\n"
  "}\n")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
