// The walk over an OpenEXR header before OpenEXR reads it (image/exr_header.h):
// files the writer makes pass, an attribute claiming more bytes than the file
// holds is named, a cut header is refused, other formats are not its business.

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "image/exr_header.h"
#include "image/image_io.h"
#include "io/atomic_file.h"
#include "support/scratch_folder.h"

namespace sdfwb::image {
namespace {

void write(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

class ExrHeader : public testing::Test {
protected:
    sdfwb::test::ScratchFolder folder;
    std::filesystem::path good = folder / "good.exr";
    void SetUp() override { writeImage(good, Image(8, 6)); }
};

TEST_F(ExrHeader, AFileTheWriterMadePasses) { EXPECT_EQ(exrHeaderProblem(good), ""); }

TEST_F(ExrHeader, AnAttributeClaimingMoreThanTheFileIsNamedBeforeOpenExrReadsIt) {
    std::string bytes = io::readTextFile(good);
    const std::size_t at = bytes.find(std::string("channels\0chlist\0", 16));
    ASSERT_NE(at, std::string::npos);
    bytes.replace(at + 16, 4, std::string("\xff\xff\xff\x70", 4));  // 1895825407 bytes
    write(folder / "bad.exr", bytes);
    std::string problem = exrHeaderProblem(folder / "bad.exr");
    EXPECT_EQ(
        problem.rfind("its OpenEXR header attribute \"channels\" claims 1895825407 bytes, past the file's end", 0), 0u)
        << problem;
    try {
        readImage(folder / "bad.exr");
        ADD_FAILURE() << "read";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find(problem), std::string::npos) << error.what();
    }
}

// OpenEXR reads at most 31 bytes of a name (255 with the long-names flag) and
// the rest as the next field: a name running on once made it read a string
// attribute of 1.9 GB from a 1.6 KB file (tests/fuzz/regressions/image).
TEST_F(ExrHeader, ANameLongerThanOpenExrReadsIsRefused) {
    const std::string bytes = io::readTextFile(good);
    const std::size_t at = bytes.find(std::string("channels\0", 9));
    ASSERT_NE(at, std::string::npos);
    const std::string longName = "channels_named_at_greater_length_than_31";
    std::string renamed = bytes;
    renamed.replace(at, 8, longName);
    write(folder / "long_name.exr", renamed);
    EXPECT_EQ(exrHeaderProblem(folder / "long_name.exr"),
              "its OpenEXR header has an attribute name or type longer than 31 bytes");
    // the version field's long-names flag (0x400, byte 5) allows up to 255
    renamed[5] = static_cast<char>(renamed[5] | 0x04);
    write(folder / "long_names_flagged.exr", renamed);
    EXPECT_EQ(exrHeaderProblem(folder / "long_names_flagged.exr"), "");
    renamed.replace(at, longName.size(), std::string(256, 'n'));
    write(folder / "too_long_even_flagged.exr", renamed);
    EXPECT_EQ(exrHeaderProblem(folder / "too_long_even_flagged.exr"),
              "its OpenEXR header has an attribute name or type longer than 255 bytes");
}

TEST_F(ExrHeader, AHeaderCutShortIsRefusedAndOtherFormatsAreLeftAlone) {
    write(folder / "cut.exr", io::readTextFile(good).substr(0, 12));  // inside the first attribute's name
    EXPECT_EQ(exrHeaderProblem(folder / "cut.exr"), "its OpenEXR header is cut short");
    writeImage(folder / "picture.png", Image(4, 4));
    EXPECT_EQ(exrHeaderProblem(folder / "picture.png"), "");
    EXPECT_EQ(exrHeaderProblem(folder / "missing.exr"), "");  // OpenImageIO says why it cannot be read
}

}  // namespace
}  // namespace sdfwb::image
