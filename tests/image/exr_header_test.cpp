// The walk over an OpenEXR header before OpenEXR reads it (image/exr_header.h):
// files the writer makes pass, an attribute claiming more bytes than the file
// holds is named, a cut header is refused, other formats are not its business.

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "image/exr_header.h"
#include "image/image_io.h"
#include "io/atomic_file.h"
#include "support/scratch_folder.h"

namespace sdfwb::image {
namespace {

std::string littleEndian32(std::uint32_t value) {
    std::string bytes;
    for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<char>(value >> shift & 0xff));
    return bytes;
}

// An attribute as a header holds it: name, type, size, value.
std::string attribute(const std::string& name, const std::string& type, const std::string& value) {
    return name + '\0' + type + '\0' + littleEndian32(static_cast<std::uint32_t>(value.size())) + value;
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
    io::writeTextAtomically(folder / "bad.exr", bytes);
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

// OpenEXR reads names of up to 255 bytes, whatever the version field's
// long-names flag says, and refuses longer ones itself.
TEST_F(ExrHeader, NamesOfUpTo255BytesPassAndLongerOnesAreRefused) {
    const std::string bytes = io::readTextFile(good);
    const std::size_t at = bytes.find(std::string("channels\0", 9));
    ASSERT_NE(at, std::string::npos);
    auto problemRenamed = [&](std::size_t length) {
        std::string renamed = bytes;
        renamed.replace(at, 8, std::string(length, 'n'));
        io::writeTextAtomically(folder / "renamed.exr", renamed);
        return exrHeaderProblem(folder / "renamed.exr");
    };
    EXPECT_EQ(problemRenamed(40), "");
    EXPECT_EQ(problemRenamed(255), "");
    EXPECT_EQ(problemRenamed(256), "its OpenEXR header has an attribute name or type longer than 255 bytes");
}

// OpenEXR reads a box at 16 bytes and a channel list up to its empty name,
// whatever their size fields say; a walk by the fields would then be at
// another place than OpenEXR. Channel lists longer than their fields twice
// hid a string of 1.9 GB from the walk (tests/fuzz/regressions/image).
TEST_F(ExrHeader, AValueOpenExrReadsAtAnotherSizeThanItsFieldIsRefused) {
    const std::string bytes = io::readTextFile(good);
    const std::string channels("channels\0chlist\0", 16);
    const std::size_t at = bytes.find(channels);
    ASSERT_NE(at, std::string::npos);
    const int listBytes = static_cast<unsigned char>(bytes[at + channels.size()]);
    for (int change : {-3, 3}) {
        std::string changed = bytes;
        changed[at + channels.size()] = static_cast<char>(listBytes + change);
        io::writeTextAtomically(folder / "changed_list.exr", changed);
        EXPECT_EQ(exrHeaderProblem(folder / "changed_list.exr"),
                  "its OpenEXR header attribute \"channels\" does not end where its size (" +
                      std::to_string(listBytes + change) + " bytes) says");
    }
    const std::string window("dataWindow\0box2i\0\x10", 18);
    const std::size_t windowAt = bytes.find(window);
    ASSERT_NE(windowAt, std::string::npos);
    std::string longBox = bytes;
    longBox[windowAt + window.size() - 1] = '\x11';
    io::writeTextAtomically(folder / "long_box.exr", longBox);
    EXPECT_EQ(exrHeaderProblem(folder / "long_box.exr"),
              "its OpenEXR header attribute \"dataWindow\" claims 17 bytes for a box2i, which OpenEXR reads as 16");
}

// A string vector is strings after their lengths, filling its size; a
// preview is a width and a height and 4 bytes a pixel; a float vector is
// whole floats. OpenEXR 3.1 reads an ID manifest past its size.
TEST_F(ExrHeader, ValuesOfVariableSizeMustFillTheirSize) {
    const std::string bytes = io::readTextFile(good);
    auto withAttribute = [&](const std::string& name, const std::string& type, const std::string& value) {
        io::writeTextAtomically(folder / "added.exr",
                                bytes.substr(0, 8) + attribute(name, type, value) + bytes.substr(8));
        return exrHeaderProblem(folder / "added.exr");
    };
    const std::string two = littleEndian32(2);
    EXPECT_EQ(withAttribute("views", "stringvector", two + "ab" + two + "cd"), "");
    EXPECT_EQ(withAttribute("runOn", "stringvector", two + "ab" + littleEndian32(3) + "cd"),
              "its OpenEXR header attribute \"runOn\" does not end where its size (12 bytes) says");
    EXPECT_EQ(withAttribute("preview", "preview", two + littleEndian32(1) + std::string(8, '\x7f')), "");
    EXPECT_EQ(withAttribute("big", "preview", littleEndian32(65535) + littleEndian32(65535) + std::string(8, '\x7f')),
              "its OpenEXR header attribute \"big\" holds a preview whose size disagrees with its width and height");
    EXPECT_EQ(withAttribute("tiny", "preview", two),
              "its OpenEXR header attribute \"tiny\" holds a preview of 4 bytes");
    EXPECT_EQ(withAttribute("weights", "floatvector", std::string(8, '\0')), "");
    EXPECT_EQ(withAttribute("weights", "floatvector", std::string(6, '\0')),
              "its OpenEXR header attribute \"weights\" holds a floatvector of 6 bytes");
    EXPECT_EQ(withAttribute("ids", "idmanifest", std::string(12, '\0')),
              "its OpenEXR header attribute \"ids\" is an ID manifest, which OpenEXR 3.1 reads past its size");
}

// A multipart file (version flag 0x1000) has headers one after another,
// ended by an empty one.
TEST_F(ExrHeader, EveryHeaderOfAMultipartFileIsWalked) {
    const std::string start = littleEndian32(20000630) + littleEndian32(2 | 0x1000);
    const std::string first = attribute("name", "string", "one") + std::string(1, '\0');
    auto problemWithSecond = [&](const std::string& second) {
        io::writeTextAtomically(folder / "parts.exr", start + first + second + std::string(2, '\0'));
        return exrHeaderProblem(folder / "parts.exr");
    };
    EXPECT_EQ(problemWithSecond(attribute("box", "box2i", std::string(16, '\0'))), "");
    EXPECT_EQ(problemWithSecond(attribute("box", "box2i", std::string(17, '\0'))),
              "its OpenEXR header attribute \"box\" claims 17 bytes for a box2i, which OpenEXR reads as 16");
}

TEST_F(ExrHeader, AHeaderCutShortIsRefusedAndOtherFormatsAreLeftAlone) {
    io::writeTextAtomically(folder / "cut.exr",
                            io::readTextFile(good).substr(0, 12));  // inside the first attribute's name
    EXPECT_EQ(exrHeaderProblem(folder / "cut.exr"), "its OpenEXR header is cut short");
    writeImage(folder / "picture.png", Image(4, 4));
    EXPECT_EQ(exrHeaderProblem(folder / "picture.png"), "");
    EXPECT_EQ(exrHeaderProblem(folder / "missing.exr"), "");  // OpenImageIO says why it cannot be read
}

}  // namespace
}  // namespace sdfwb::image
