#include "image/image_io.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "image/encoding.h"
#include "image/exr_header.h"
#include "image/jpeg_markers.h"
#include "image/png_chunks.h"
#include "io/atomic_file.h"

namespace sdfwb::image {
namespace {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// Opens `path` with the reader of its extension alone, or returns null with
// the reason. OpenImageIO's own open() tries every reader it has when that one
// fails (camera raw, FITS, DPX and more): decoders nobody meant to run on the
// file, and a wide surface for a hostile one.
std::unique_ptr<OIIO::ImageInput> openByExtension(const std::filesystem::path& path, std::string& reason) {
    const std::string extension = lowerExtension(path);
    // the extension without its dot names a reader; with it, or as a file's
    // name, OpenImageIO would look for a file and probe it
    auto in = extension.size() > 1 ? OIIO::ImageInput::create(extension.substr(1)) : nullptr;
    if (!in) {
        OIIO::geterror();  // OpenImageIO's message names a plugin search, not the file
        reason = extension.empty() ? "a file without an extension has no image reader"
                                   : "no image reader for '" + extension + "' files";
        return nullptr;
    }
    OIIO::ImageSpec spec;
    if (!in->open(path.string(), spec)) {
        reason = in->geterror();
        if (reason.empty()) reason = "not a " + std::string(in->format_name()) + " file";
        return nullptr;
    }
    return in;
}

// Some writers report success on a full disk and leave a truncated file (the
// PNG writer does): only a file that decodes completely may replace the old one.
void checkReadsBack(const std::filesystem::path& temporary, const std::filesystem::path& path, const Image& image) {
    std::string reason;
    auto in = openByExtension(temporary, reason);
    bool ok = in && in->spec().width == image.width && in->spec().height == image.height;
    if (ok) {
        std::vector<std::byte> stored(in->spec().image_bytes(true));
        ok = in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::UNKNOWN, stored.data());
    }
    if (!ok) {
        if (in) reason = in->geterror();
        throw std::runtime_error("cannot write " + path.string() + ": the written file does not read back" +
                                 (reason.empty() ? std::string(" (is the disk full?)") : ": " + reason));
    }
}

}  // namespace

bool isDisplayEncoded(const std::filesystem::path& path) { return lowerExtension(path) != ".exr"; }

void checkWritableFormat(const std::filesystem::path& path) {
    static const std::vector<std::string> known = {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr"};
    std::string ext = lowerExtension(path);
    if (std::find(known.begin(), known.end(), ext) == known.end()) {
        throw std::runtime_error(path.string() + ": unknown image format '" + (ext.empty() ? std::string("(none)") : ext) +
                                 "' (use .png, .exr, .tif or .jpg)");
    }
}

void writeImage(const std::filesystem::path& path, const Image& image, const Metadata& metadata) {
    io::StagedWrites writes;
    stageImage(writes, path, image, metadata);
    writes.commit();
}

void stageImage(io::StagedWrites& writes, const std::filesystem::path& path, const Image& image,
                const Metadata& metadata) {
    checkWritableFormat(path);
    writes.stage(path, [&](const std::filesystem::path& temporary) {
        auto out = OIIO::ImageOutput::create(temporary.string());
        if (!out) {
            throw std::runtime_error("cannot write " + path.string() + ": " + OIIO::geterror());
        }
        // Encoded in memory where the writer allows it: libjpeg exits the
        // process on a write error, and libpng can report success on a full
        // disk; the bytes are then written, and checked, here. Not TIFF:
        // OpenImageIO 2.4 writes it through a proxy without its ImageLength.
        std::vector<unsigned char> encoded;
        OIIO::Filesystem::IOVecOutput memory(encoded);
        const std::string extension = lowerExtension(path);
        const bool inMemory = extension != ".tif" && extension != ".tiff" && out->supports("ioproxy") &&
                              out->set_ioproxy(&memory);
        bool display = isDisplayEncoded(path);
        OIIO::ImageSpec spec(image.width, image.height, 3, display ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
        spec.attribute("oiio:ColorSpace", display ? "sRGB" : "Linear");
        spec.attribute("Software", "SDF Workbench");
        for (const auto& [key, value] : metadata) {
            spec.attribute(key, value);
        }
        if (!out->open(temporary.string(), spec)) {
            throw std::runtime_error("cannot write " + path.string() + ": " + out->geterror());
        }
        bool ok = false;
        if (display) {
            std::vector<std::uint8_t> bytes = encodeSrgb8(image);
            ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
        } else {
            ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data());
        }
        std::string error = ok ? "" : out->geterror();
        if (!out->close() && ok) {
            error = out->geterror();
            ok = false;
        }
        if (!ok) {
            throw std::runtime_error("cannot write " + path.string() + ": " + error);
        }
        if (inMemory) {
            io::writeContent(temporary, path,
                             std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
        }
        checkReadsBack(temporary, path, image);
    });
}

Image readImage(const std::filesystem::path& path, std::size_t maxPixels, PixelValues values) {
    for (std::string problem : {exrHeaderProblem(path), pngChunkProblem(path), jpegMarkerProblem(path)}) {
        if (!problem.empty()) throw std::runtime_error("cannot read image " + path.string() + ": " + problem);
    }
    std::string reason;
    auto in = openByExtension(path, reason);
    if (!in) {
        throw std::runtime_error("cannot read image " + path.string() + ": " + reason);
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels <= 0 || spec.width <= 0 || spec.height <= 0 ||
        static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) > maxPixels) {
        throw std::runtime_error("cannot read image " + path.string() + ": it is " + std::to_string(spec.width) +
                                 " x " + std::to_string(spec.height) + " pixels of " +
                                 std::to_string(spec.nchannels) + " channels; at most " +
                                 std::to_string(maxPixels) + " pixels are read here");
    }
    Image image(spec.width, spec.height);
    // colour is the first three channels, or the first one (grey, with or
    // without alpha) for all three
    const int channels = spec.nchannels >= 3 ? 3 : 1;
    const bool eightBit = spec.format == OIIO::TypeDesc::UINT8;
    // 16-bit PNGs and TIFFs store the display encoding as 8-bit ones do
    // (OpenImageIO hands them over as fractions of 65535, not decoded)
    const bool displayEncoded = eightBit || spec.format == OIIO::TypeDesc::UINT16;
    // An image of up to four channels of one type is read as stored, every
    // channel, and converted here: asked for another type or for some of its
    // channels, OpenImageIO converts through a buffer of about 64 MB per read
    // whatever the image's size (48 MB for a 256 x 256 RGBA PNG). Others (many
    // channels, or channels of different types) are read as the first
    // `channels` in the type wanted, so they cost no more memory than RGB.
    const OIIO::TypeDesc wanted = eightBit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
    const std::size_t storedCount = image.pixelCount() * static_cast<std::size_t>(spec.nchannels);
    const bool asStored = spec.nchannels <= 4 && spec.channelformats.empty() &&
                          storedCount <= static_cast<std::size_t>(std::numeric_limits<int>::max());
    const int stride = asStored ? spec.nchannels : channels;
    const std::size_t count = image.pixelCount() * static_cast<std::size_t>(stride);
    std::vector<float> pixels(eightBit ? 0 : count);
    std::vector<std::uint8_t> bytes(eightBit ? count : 0);
    void* const destination = eightBit ? static_cast<void*>(bytes.data()) : static_cast<void*>(pixels.data());
    bool ok = false;
    if (!asStored) {
        ok = in->read_image(0, 0, 0, channels, wanted, destination);
    } else if (spec.format == wanted) {
        ok = in->read_image(0, 0, 0, stride, OIIO::TypeDesc::UNKNOWN, destination);
    } else {
        // a second copy, of the stored type, only where the types differ
        std::vector<std::byte> stored(spec.image_bytes(true));
        ok = in->read_image(0, 0, 0, stride, OIIO::TypeDesc::UNKNOWN, stored.data()) &&
             OIIO::convert_pixel_values(spec.format, stored.data(), wanted, destination, static_cast<int>(count));
    }
    if (!ok) {
        throw std::runtime_error("cannot read image " + path.string() + ": " + in->geterror());
    }
    in->close();
    const bool decode = displayEncoded && values == PixelValues::Colour;
    auto value = [&](size_t source) {
        if (eightBit) return decode ? decodeSrgb8(bytes[source]) : static_cast<float>(bytes[source]) / 255.0f;
        return decode ? linearFromSrgb(pixels[source]) : pixels[source];
    };
    for (size_t i = 0; i < image.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c) {
            size_t source = i * static_cast<size_t>(stride) + static_cast<size_t>(std::min(c, channels - 1));
            image.rgb[3 * i + static_cast<size_t>(c)] = value(source);
        }
    }
    return image;
}

}  // namespace sdfwb::image
