#include "sdf/glsl_sources.h"

namespace sdfwb::sdf {

std::string_view glslPrelude() {
    return "#define real float\n"
           "#define SHARED_FN\n"
           "#define librarySin formulaSin\n"
           "#define libraryCos formulaCos\n";
}

}  // namespace sdfwb::sdf
