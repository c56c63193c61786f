#include "rt/io/png_check.hpp"

#include <stb_image.h>
#include <zlib.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"

namespace rt {

namespace {

// CRC-32 as PNG computes it (ISO 3309), by zlib.
std::uint32_t crc32_of(std::string_view bytes) {
    return std::uint32_t(::crc32_z(::crc32_z(0, nullptr, 0), reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

std::uint32_t big_endian(std::string_view four) {
    std::uint32_t n = 0;
    for (const char b : four) n = (n << 8) | static_cast<unsigned char>(b);
    return n;
}

struct Chunk {
    std::string_view type;  // four letters, "IHDR"
    std::string_view data;
    std::size_t offset;  // of its length field, from the file's start
};

// The chunks after the 8-byte signature, up to IEND, each with its CRC checked.
std::vector<Chunk> chunks_of(std::string_view png) {
    std::vector<Chunk> chunks;
    std::size_t at = 8;
    while (chunks.empty() || chunks.back().type != "IEND") {
        if (at > png.size() || png.size() - at < 12) {
            throw InputError("byte " + std::to_string(at) +
                             ": the file ends before its IEND chunk (truncated)");
        }
        const std::uint32_t length = big_endian(png.substr(at, 4));
        const std::string_view type = png.substr(at + 4, 4);
        const std::string where = "chunk " + printable(type) + " at byte " + std::to_string(at) + ": ";
        if (length > png.size() - at - 12) {
            throw InputError(where + "its " + std::to_string(length) +
                             " bytes of data run past the end of the file (truncated)");
        }
        if (crc32_of(png.substr(at + 4, 4 + length)) != big_endian(png.substr(at + 8 + length, 4))) {
            throw InputError(where + "its CRC does not match its data (the file is damaged)");
        }
        chunks.push_back({type, png.substr(at + 8, length), at});
        at += 12 + std::size_t(length);
    }
    return chunks;
}

void append_chunk(std::string& png, std::string_view type, std::string_view data) {
    for (int shift = 24; shift >= 0; shift -= 8) png += char((data.size() >> shift) & 0xffu);
    const std::size_t start = png.size();
    png.append(type).append(data);
    const std::uint32_t crc = crc32_of(std::string_view(png).substr(start));
    for (int shift = 24; shift >= 0; shift -= 8) png += char((crc >> shift) & 0xffu);
}

// A paletted image whose palette has fewer colours than its bit depth can index: decoded once more by
// stb_image, from a copy whose PLTE is padded to 256 colours and whose tRNS makes exactly the padding
// transparent, so a transparent pixel is one whose index is past the palette.
void check_palette_indices(std::string_view png, const std::vector<Chunk>& chunks) {
    const Chunk& header = chunks.front();
    const bool paletted = header.type == "IHDR" && header.data.size() == 13 && header.data[9] == 3;
    const Chunk* palette = nullptr;
    for (const Chunk& c : chunks) palette = c.type == "PLTE" ? &c : palette;
    if (!paletted || !palette || palette->data.size() % 3 != 0 || palette->data.size() > 256 * 3) return;
    const std::size_t colours = palette->data.size() / 3;
    const int bit_depth = header.data[8];
    if (bit_depth < 1 || bit_depth > 8 || colours >= (std::size_t(1) << bit_depth)) return;
    std::string marked(png.substr(0, 8));
    for (const Chunk& c : chunks) {
        if (c.type == "tRNS") continue;
        if (&c != palette) {
            marked.append(png.substr(c.offset, 12 + c.data.size()));
            continue;
        }
        std::string padded(c.data);
        padded.resize(256 * 3, '\0');
        append_chunk(marked, "PLTE", padded);
        std::string alpha(colours, '\xff');
        alpha.resize(256, '\0');
        append_chunk(marked, "tRNS", alpha);
    }
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> rgba(
        stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(marked.data()), int(marked.size()), &width,
                              &height, &channels, 4),
        stbi_image_free);
    if (!rgba) return;  // the file itself is refused when decoded, with stb_image's reason
    const std::size_t count = std::size_t(width) * std::size_t(height);
    for (std::size_t i = 0; i < count; ++i) {
        if (rgba.get()[4 * i + 3] != 0) continue;
        throw InputError("pixel (" + std::to_string(i % std::size_t(width)) + ", " +
                         std::to_string(i / std::size_t(width)) + "): its palette index is past the " +
                         std::to_string(colours) + " colour(s) of the PLTE chunk");
    }
}

}  // namespace

void check_png(std::string_view png) {
    check_palette_indices(png, chunks_of(png));
}

}  // namespace rt
