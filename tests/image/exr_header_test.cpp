// The walk over an OpenEXR header before OpenEXR reads it (image/exr_header.h):
// files the writer makes pass, an attribute claiming more bytes than the file
// holds is named, a cut header is refused, other formats are not its business.

#include <cstdint>
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

// OpenEXR reads a box at 16 bytes and a channel list up to its empty name,
// whatever their size fields say; a walk by the fields would then be at
// another place than OpenEXR. A channel list 3 bytes longer than its field
// once hid a string of 1.9 GB from the walk (tests/fuzz/regressions/image).
TEST_F(ExrHeader, AValueOpenExrReadsAtAnotherSizeThanItsFieldIsRefused) {
    const std::string bytes = io::readTextFile(good);
    const std::string channels("channels\0chlist\0", 16);
    const std::size_t at = bytes.find(channels);
    ASSERT_NE(at, std::string::npos);
    std::string shortList = bytes;
    shortList[at + channels.size()] = static_cast<char>(shortList[at + channels.size()] - 3);
    write(folder / "short_list.exr", shortList);
    const std::uint32_t listBytes = static_cast<unsigned char>(shortList[at + channels.size()]);
    EXPECT_EQ(exrHeaderProblem(folder / "short_list.exr"),
              "its OpenEXR header attribute \"channels\" does not end "
              "where its size (" +
                  std::to_string(listBytes) + " bytes) says");
    const std::string window("dataWindow\0box2i\0\x10", 18);
    const std::size_t windowAt = bytes.find(window);
    ASSERT_NE(windowAt, std::string::npos);
    std::string longBox = bytes;
    longBox[windowAt + window.size() - 1] = '\x11';
    write(folder / "long_box.exr", longBox);
    EXPECT_EQ(exrHeaderProblem(folder / "long_box.exr"),
              "its OpenEXR header attribute \"dataWindow\" claims 17 bytes for a box2i, which OpenEXR reads as 16");
}

// A string vector is strings after their lengths, filling its size; a
// preview is a width and a height and 4 bytes a pixel.
TEST_F(ExrHeader, StringVectorsAndPreviewsMustFillTheirSize) {
    const std::string bytes = io::readTextFile(good);
    auto withAttribute = [&](const std::string& name, const std::string& type, const std::string& value) {
        const std::uint32_t size = static_cast<std::uint32_t>(value.size());
        std::string attribute = name + '\0' + type + '\0';
        for (int shift = 0; shift < 32; shift += 8) attribute.push_back(static_cast<char>(size >> shift & 0xff));
        const std::filesystem::path path = folder / (name + ".exr");
        write(path, bytes.substr(0, 8) + attribute + value + bytes.substr(8));
        return exrHeaderProblem(path);
    };
    const std::string two("\x02\0\0\0", 4);
    EXPECT_EQ(withAttribute("views", "stringvector", two + "ab" + two + "cd"), "");
    EXPECT_EQ(withAttribute("runOn", "stringvector", two + "ab" + std::string("\x03\0\0\0", 4) + "cd"),
              "its OpenEXR header attribute \"runOn\" does not end where its size (12 bytes) says");
    const std::string twoByOne = two + std::string("\x01\0\0\0", 4);
    EXPECT_EQ(withAttribute("preview", "preview", twoByOne + std::string(8, '\x7f')), "");
    EXPECT_EQ(
        withAttribute("bigPreview", "preview", std::string("\xff\xff\0\0\xff\xff\0\0", 8) + std::string(8, '\x7f')),
        "its OpenEXR header attribute \"bigPreview\" holds a preview whose size disagrees with its width and "
        "height");
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
