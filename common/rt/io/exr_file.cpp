#include "rt/io/exr_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#ifdef RT_HAVE_OPENEXR
#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <half.h>
#endif

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/staged_file.hpp"

namespace rt {
namespace fs = std::filesystem;

namespace {

#ifndef RT_HAVE_OPENEXR
constexpr const char* kNotBuilt =
    "OpenEXR files are not read or written by this build (install libopenexr-dev "
    "and configure again)";
#else
constexpr const char* kChannelNames[3] = {"R", "G", "B"};

// OpenEXR writes through an OStream: this one is the staging file's, and it throws when a write fails (the
// library then stops, and encode_exr says so).
class StagedStream : public Imf::OStream {
  public:
    explicit StagedStream(std::FILE* file) : Imf::OStream("the staging file"), file_(file) {}
    void write(const char c[], int n) override {
        if (!write_bytes(file_, c, std::size_t(n))) Iex::throwErrnoExc();
    }
    uint64_t tellp() override { return uint64_t(::ftello(file_)); }
    void seekp(uint64_t pos) override {
        if (::fseeko(file_, off_t(pos), SEEK_SET) != 0) Iex::throwErrnoExc();
    }

  private:
    std::FILE* file_;
};

// The image's channels, interleaved R G B, as the file's type (OpenEXR writes a slice of the channel's own
// type): floats, or half floats each clamped to ±kHalfMax and rounded to the nearest.
template <typename Channel>
std::vector<Channel> interleaved(const Image& image) {
    std::vector<Channel> rgb;
    rgb.reserve(image.pixel_count() * 3);
    for (const Color& c : image.pixels()) {
        for (int i = 0; i < 3; ++i) {
            const float v = float(c[i]);
            rgb.push_back(std::is_same_v<Channel, half> ? Channel(std::clamp(v, -kHalfMax, kHalfMax))
                                                        : Channel(v));
        }
    }
    return rgb;
}

// The EXR of `rgb`, interleaved channels of the type `type`, through `stream`.
template <typename Channel>
void write_rgb(Imf::OStream& stream, const std::vector<Channel>& rgb, Imf::PixelType type, int width,
               int height) {
    Imf::Header header(width, height);  // ZIP compression, the data window from (0, 0)
    Imf::FrameBuffer frame;
    for (int i = 0; i < 3; ++i) {
        header.channels().insert(kChannelNames[i], Imf::Channel(type));
        frame.insert(kChannelNames[i],
                     Imf::Slice(type, const_cast<char*>(reinterpret_cast<const char*>(rgb.data() + i)),
                                3 * sizeof(Channel), std::size_t(width) * 3 * sizeof(Channel)));
    }
    Imf::OutputFile out(stream, header);
    out.setFrameBuffer(frame);
    out.writePixels(height);
}

// Refuses a file that lacks R, G or B, naming the channels it has.
void check_rgb_channels(const Imf::ChannelList& list, const std::string& name) {
    std::string have;
    for (auto c = list.begin(); c != list.end(); ++c)
        have += (have.empty() ? "" : ", ") + printable(c.name());
    for (const char* channel : kChannelNames) {
        if (!list.findChannel(channel)) {
            throw InputError(name + ": must hold the channels R, G and B, got " +
                             (have.empty() ? std::string("none") : have));
        }
    }
}

// The data window's pixels as floats, R G B interleaved; the file must hold every one of them.
std::vector<float> read_rgb(Imf::InputFile& file, const Imath::Box2i& window, long long width,
                            long long height, const std::string& name) {
    std::vector<float> rgb(std::size_t(width) * std::size_t(height) * 3);
    Imf::FrameBuffer frame;
    for (int i = 0; i < 3; ++i) {
        frame.insert(kChannelNames[i], Imf::Slice::Make(Imf::FLOAT, rgb.data() + i, window, 3 * sizeof(float),
                                                        std::size_t(width) * 3 * sizeof(float)));
    }
    file.setFrameBuffer(frame);
    if (!file.isComplete()) throw InputError(name + ": OpenEXR data is truncated (the file is incomplete)");
    file.readPixels(window.min.y, window.max.y);
    return rgb;
}
#endif

}  // namespace

bool has_openexr() {
#ifdef RT_HAVE_OPENEXR
    return true;
#else
    return false;
#endif
}

std::size_t beyond_half_range(const Image& image) {
    std::size_t count = 0;
    for (const Color& c : image.pixels())
        for (int i = 0; i < 3; ++i) count += std::abs(float(c[i])) > kHalfMax ? 1 : 0;
    return count;
}

bool encode_exr(const Image& image, ExrChannels channels, std::FILE* file) {
#ifdef RT_HAVE_OPENEXR
    try {
        StagedStream stream(file);
        if (channels == ExrChannels::kHalf)
            write_rgb(stream, interleaved<half>(image), Imf::HALF, image.width(), image.height());
        else
            write_rgb(stream, interleaved<float>(image), Imf::FLOAT, image.width(), image.height());
    } catch (const std::exception&) {
        return false;  // errno says why, where a write failed
    }
    return true;
#else
    (void)image, (void)channels, (void)file;
    throw InputError(kNotBuilt);
#endif
}

void write_exr(const Image& image, const fs::path& path, ExrChannels channels) {
    StagedFile exr(path);
    write_staged(exr, [&](std::FILE* file) { return encode_exr(image, channels, file); });
    exr.commit();
}

Image read_exr(const fs::path& path, PfmPixels pixels) {
    const std::string name = shown(path);
#ifdef RT_HAVE_OPENEXR
    check_regular_file(path, "an OpenEXR file");
    try {
        Imf::InputFile file(path.c_str());
        check_rgb_channels(file.header().channels(), name);
        const Imath::Box2i window = file.header().dataWindow();
        const long long width = (long long)(window.max.x) - window.min.x + 1;
        const long long height = (long long)(window.max.y) - window.min.y + 1;
        try {
            check_image_size(width, height);
        } catch (const InputError& e) {
            throw InputError(name + ": " + e.what());
        }
        const std::vector<float> rgb = read_rgb(file, window, width, height, name);
        Image image{int(width), int(height)};
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                const float* p = rgb.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
                const Color c(p[0], p[1], p[2]);
                check_read_pixel(name, c, x, y, pixels);
                image.at(x, y) = c;
            }
        }
        return image;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(name + ": must be an OpenEXR file it can read (" + printable(e.what()) + ")");
    }
#else
    (void)pixels;
    throw InputError(name + ": " + kNotBuilt);
#endif
}

Image read_radiance(const fs::path& path, PfmPixels pixels) {
    return path.extension() == ".exr" ? read_exr(path, pixels) : read_pfm(path, pixels);
}

}  // namespace rt
