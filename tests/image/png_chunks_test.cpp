// The walk over a PNG's chunks before libpng reads them (image/png_chunks.h):
// files the writer makes pass, a chunk claiming more bytes than the file
// holds is named, other formats are not its business.

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "image/png_chunks.h"
#include "io/atomic_file.h"
#include "support/scratch_folder.h"

namespace sdfwb::image {
namespace {

class PngChunks : public testing::Test {
protected:
    sdfwb::test::ScratchFolder folder;
    std::filesystem::path good = folder / "good.png";
    void SetUp() override { writeImage(good, Image(8, 6)); }
};

TEST_F(PngChunks, AFileTheWriterMadePassesAndOtherFormatsAreLeftAlone) {
    EXPECT_EQ(pngChunkProblem(good), "");
    writeImage(folder / "picture.exr", Image(4, 4));
    EXPECT_EQ(pngChunkProblem(folder / "picture.exr"), "");
    EXPECT_EQ(pngChunkProblem(folder / "missing.png"), "");  // OpenImageIO says why it cannot be read
}

// libpng allocates a text chunk at its claimed length before reading it: an
// 838-byte file once took 1.6 GB (tests/fuzz/regressions/image).
TEST_F(PngChunks, AChunkClaimingMoreThanTheFileIsNamedBeforeLibpngReadsIt) {
    std::string bytes = io::readTextFile(good);
    const std::size_t iend = bytes.find("IEND");
    ASSERT_NE(iend, std::string::npos);
    // a tEXt chunk of 1634811467 claimed bytes in front of IEND, holding 4
    const std::string chunk = std::string("\x61\x71\x3e\x4b", 4) + std::string("tEXtkey\0", 8) + "CRC!";
    bytes.insert(iend - 4, chunk);
    const std::filesystem::path bad = folder / "bad.png";
    std::ofstream(bad, std::ios::binary) << bytes;
    const std::string problem = pngChunkProblem(bad);
    EXPECT_EQ(problem, "its PNG chunk \"tEXt\" claims 1634811467 bytes, past the file's end (" +
                           std::to_string(bytes.size()) + " bytes)");
    try {
        readImage(bad);
        ADD_FAILURE() << "read";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find(problem), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace sdfwb::image
