// FNV-1a, 64 bits: the checksum of a film file and the fingerprint of a scene's files. Not cryptographic: it
// catches corruption and edits, not forgery.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace rt {

inline constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ull;

inline std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = kFnvOffset) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
    return hash;
}
inline std::uint64_t fnv1a(std::string_view text, std::uint64_t hash = kFnvOffset) {
    return fnv1a(text.data(), text.size(), hash);
}

}  // namespace rt
