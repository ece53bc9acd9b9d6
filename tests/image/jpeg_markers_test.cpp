// The walk over a JPEG's IPTC block before OpenImageIO decodes it
// (image/jpeg_markers.h): files with a caption pass, a record claiming more
// bytes than its block holds is named, other formats are not its business.

#include <fstream>
#include <string>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "image/image_io.h"
#include "image/jpeg_markers.h"
#include "io/atomic_file.h"
#include "support/scratch_folder.h"

namespace sdfwb::image {
namespace {

class JpegMarkers : public testing::Test {
protected:
    sdfwb::test::ScratchFolder folder;
    std::filesystem::path captioned = folder / "captioned.jpg";
    // OpenImageIO writes a caption as an IPTC record in a Photoshop APP13 segment
    void SetUp() override {
        auto out = OIIO::ImageOutput::create(captioned.string());
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(4, 4, 3, OIIO::TypeDesc::UINT8);
        spec.attribute("ImageDescription", "a caption of some length");
        ASSERT_TRUE(out->open(captioned.string(), spec));
        const std::string pixels(4 * 4 * 3, '\x80');
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
        ASSERT_TRUE(out->close());
    }
};

TEST_F(JpegMarkers, ACaptionedFilePassesAndOtherFormatsAreLeftAlone) {
    ASSERT_NE(io::readTextFile(captioned).find(std::string("Photoshop 3.0\0008BIM\004\004", 20)), std::string::npos);
    EXPECT_EQ(jpegMarkerProblem(captioned), "");
    EXPECT_NO_THROW(readImage(captioned));
    writeImage(folder / "picture.png", Image(4, 4));
    EXPECT_EQ(jpegMarkerProblem(folder / "picture.png"), "");
    EXPECT_EQ(jpegMarkerProblem(folder / "missing.jpg"), "");  // OpenImageIO says why it cannot be read
}

// OpenImageIO 2.4 copies a record at the size it claims: past its block, it
// read past the segment (tests/fuzz/regressions/image).
TEST_F(JpegMarkers, ARecordClaimingMoreThanItsBlockIsNamedBeforeOpenImageIoReadsIt) {
    std::string bytes = io::readTextFile(captioned);
    const std::size_t at = bytes.find(std::string("Photoshop 3.0\0008BIM", 18));
    ASSERT_NE(at, std::string::npos);
    const std::size_t record = at + 26;  // signature 14, 8BIM 4, id 2, skipped 4, size 2
    ASSERT_EQ(bytes[record], '\x1c');
    bytes[record + 3] = '\x7f';
    bytes[record + 4] = '\xff';
    const std::filesystem::path bad = folder / "bad.jpg";
    std::ofstream(bad, std::ios::binary) << bytes;
    const std::string problem = jpegMarkerProblem(bad);
    EXPECT_EQ(problem.rfind("its JPEG IPTC record claims 32767 bytes, past the end of its block (", 0), 0u) << problem;
    try {
        readImage(bad);
        ADD_FAILURE() << "read";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find(problem), std::string::npos) << error.what();
    }
    // libjpeg skips bytes that are no marker up to the next 0xFF, and so does the walk
    const std::size_t segment = bytes.rfind('\xff', at);
    ASSERT_NE(segment, std::string::npos);
    bytes.insert(segment, "garbage");
    std::ofstream(bad, std::ios::binary | std::ios::trunc) << bytes;
    EXPECT_EQ(jpegMarkerProblem(bad), problem);
}

}  // namespace
}  // namespace sdfwb::image
