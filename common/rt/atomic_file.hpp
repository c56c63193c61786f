// Writing a file all or nothing: into a temporary file beside it, then renamed over it.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <functional>

namespace rt {

// Writes through `write_to(file)` into a temporary file beside `path`, then renames it over `path`: all or
// nothing. Every write, the flush and the close are checked, so a full disk cannot leave a truncated file.
// Throws InputError (unwritable path) or std::runtime_error (write failure); an earlier file is left as it
// was.
void write_atomically(const std::filesystem::path& path, const std::function<bool(std::FILE*)>& write_to);

// fwrite that says whether every byte was written.
bool write_bytes(std::FILE* file, const void* data, std::size_t size);

}  // namespace rt
