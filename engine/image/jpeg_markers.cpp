#include "image/jpeg_markers.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

namespace sdfwb::image {
namespace {

constexpr unsigned char kMarker = 0xff;
constexpr unsigned char kStartOfImage = 0xd8;
constexpr unsigned char kEndOfImage = 0xd9;
constexpr unsigned char kStartOfScan = 0xda;
constexpr unsigned char kFirstRestart = 0xd0;  // RST0 to RST7 and SOI carry no length, as TEM
constexpr unsigned char kTemporary = 0x01;
constexpr unsigned char kApp13 = 0xed;
// What OpenImageIO's reader expects before the IPTC records: the Photoshop
// signature, an 8BIM resource of id 1028, four bytes it skips and the
// records' size in two bytes.
constexpr char kPhotoshop[] = "Photoshop 3.0";  // with its NUL, 14 bytes
constexpr std::size_t kIptcHeader = sizeof(kPhotoshop) + 4 + 2 + 4 + 2;
constexpr std::size_t kRecordHeader = 5;  // 0x1C, record (1 or 2), dataset, size in two bytes

unsigned bigEndian16(const unsigned char* b) { return unsigned(b[0]) << 8 | unsigned(b[1]); }

std::string iptcProblem(const std::vector<unsigned char>& segment) {
    if (segment.size() < kIptcHeader || std::memcmp(segment.data(), kPhotoshop, sizeof(kPhotoshop)) != 0 ||
        std::memcmp(segment.data() + sizeof(kPhotoshop), "8BIM", 4) != 0 ||
        bigEndian16(segment.data() + sizeof(kPhotoshop) + 4) != 1028) {
        return "";  // not the block the reader decodes
    }
    const std::size_t block = bigEndian16(segment.data() + kIptcHeader - 2);
    const std::size_t available = segment.size() - kIptcHeader;
    if (block > available) {
        return "its JPEG IPTC block claims " + std::to_string(block) + " bytes, past the end of its segment (" +
               std::to_string(available) + " bytes)";
    }
    // the records, as the reader takes them: while bytes are left and one starts with 0x1C 0x01 or 0x1C 0x02
    const unsigned char* record = segment.data() + kIptcHeader;
    for (std::size_t left = block; left > 0 && record[0] == 0x1c;) {
        if (left < kRecordHeader) {
            return "its JPEG IPTC block ends inside a record's header";
        }
        if (record[1] != 0x01 && record[1] != 0x02) return "";
        const std::size_t size = bigEndian16(record + 3);
        if (size > left - kRecordHeader) {
            return "its JPEG IPTC record claims " + std::to_string(size) + " bytes, past the end of its block (" +
                   std::to_string(left - kRecordHeader) + " bytes)";
        }
        record += kRecordHeader + size;
        left -= kRecordHeader + size;
    }
    return "";
}

// The next marker's code as libjpeg finds it (next_marker in jdmarker.c):
// bytes up to an 0xFF are skipped, then fill bytes of 0xFF; an 0xFF 0x00 is
// no marker. -1 at the file's end.
int nextMarker(std::istream& in) {
    for (char c; in.get(c);) {
        if (static_cast<unsigned char>(c) != kMarker) continue;
        while (in.get(c) && static_cast<unsigned char>(c) == kMarker) {}
        if (!in) return -1;
        if (c != 0) return static_cast<unsigned char>(c);
    }
    return -1;
}

}  // namespace

std::string jpegMarkerProblem(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char start[2];
    if (!in.read(reinterpret_cast<char*>(start), 2) || start[0] != kMarker || start[1] != kStartOfImage) return "";
    // each segment takes at least 2 bytes of the file, so the walk ends at its end or at the scan
    for (int marker; (marker = nextMarker(in)) >= 0;) {
        if (marker == kStartOfScan || marker == kEndOfImage) return "";  // libjpeg's to judge from here
        if (marker == kTemporary || (marker >= kFirstRestart && marker <= kStartOfImage)) continue;  // no length
        unsigned char length[2];
        if (!in.read(reinterpret_cast<char*>(length), 2) || bigEndian16(length) < 2) return "";
        std::vector<unsigned char> segment(bigEndian16(length) - 2);
        if (!in.read(reinterpret_cast<char*>(segment.data()), static_cast<std::streamsize>(segment.size()))) return "";
        if (marker == kApp13) {
            if (std::string problem = iptcProblem(segment); !problem.empty()) return problem;
        }
    }
    return "";
}

}  // namespace sdfwb::image
