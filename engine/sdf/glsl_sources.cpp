#include "sdf/glsl_sources.h"

namespace sdfwb::sdf {

std::string_view glslPrelude() {
    return "#define real float\n"
           "#define SHARED_FN\n"
           "#define librarySin formulaSin\n"
           "#define libraryCos formulaCos\n"
           "#define libraryExp2 formulaExp2\n"
           "#define libraryLog2 formulaLog2\n"
           "#define libraryAtan2 formulaAtan2\n";
}

std::string sharedShadingCode() {
    std::string text;
    for (std::string_view part : {glslPrelude(), glslLibrary(), glslSampleDriver(), glslTextureLookup(),
                                  glslEnvironmentLookup(), glslPruneLookup()}) {
        text.append(part).append("\n");
    }
    return text;
}

}  // namespace sdfwb::sdf
