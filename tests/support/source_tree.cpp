#include "support/source_tree.h"

namespace sdfwb::test {

std::string sourceDir() { return SDFWB_SOURCE_DIR; }
std::string outputDir() { return SDFWB_TEST_OUTPUT_DIR; }

}  // namespace sdfwb::test
