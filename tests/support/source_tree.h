#pragma once
// Where the tests find the checkout's files and write their outputs. Defined in
// one translation unit (source_tree.cpp), so that no other test object carries
// the checkout's path and a compiler cache can share them between checkouts.

#include <string>

namespace sdfwb::test {

// The source tree's root, without a trailing slash.
std::string sourceDir();
// The build tree's test-output folder (failure images, candidate goldens).
std::string outputDir();

}  // namespace sdfwb::test
