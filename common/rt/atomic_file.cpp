#include "rt/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include "rt/image_io.hpp"

namespace rt {
namespace fs = std::filesystem;
namespace {

// What went wrong, from errno, for a message: " (No space left on device)".
std::string system_reason(int error) {
    return error != 0 ? " (" + std::string(std::strerror(error)) + ")" : "";
}

}  // namespace

void write_atomically(const fs::path& path, const std::function<bool(std::FILE*)>& write_to) {
    check_writable(path);
    const fs::path temporary = path.string() + ".partial-" + std::to_string(::getpid());
    errno = 0;
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) {
        throw std::runtime_error(path.string() + ": could not create " + temporary.string() +
                                 system_reason(errno));
    }
    bool ok = write_to(file);
    ok = std::fflush(file) == 0 && ok;
    const int error = errno;
    ok = std::fclose(file) == 0 && ok;
    std::error_code ec;
    if (!ok) {
        fs::remove(temporary, ec);
        throw std::runtime_error(path.string() + ": could not write the file" +
                                 system_reason(error ? error : errno) +
                                 "; an earlier file of that name is left as it was");
    }
    fs::rename(temporary, path, ec);
    if (ec) {
        fs::remove(temporary, ec);
        throw std::runtime_error(path.string() +
                                 ": could not rename the finished file into place: " + ec.message());
    }
}

bool write_bytes(std::FILE* file, const void* data, std::size_t size) {
    return std::fwrite(data, 1, size, file) == size;
}

}  // namespace rt
