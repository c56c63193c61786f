#include "rt/io/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <new>
#include <system_error>

#include "rt/core/errors.hpp"

namespace rt {
namespace fs = std::filesystem;

std::string not_a_regular_file(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    switch (status.type()) {
        case fs::file_type::regular:
            return "";
        case fs::file_type::not_found:
            return "no such file";
        case fs::file_type::directory:
            return "a folder";
        case fs::file_type::none:  // no status: a link loop, a folder on the way that cannot be searched, ...
            return "a path that cannot be followed (" + ec.message() + ")";
        default:
            return "something else than a file (a device, a pipe or a socket)";
    }
}

std::string read_whole_file(const fs::path& path) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InputError(std::string("cannot be opened for reading") +
                         (errno != 0 ? " (" + std::string(std::strerror(errno)) + ")" : ""));
    }
    try {
        std::string text;
        if (!ec) text.reserve(size);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (in.bad()) throw InputError("cannot be read (a read failed)");
        return text;
    } catch (const std::ios_base::failure& e) {
        throw InputError("cannot be read (" + std::string(e.code().message()) + ")");
    } catch (const std::bad_alloc&) {
        throw InputError("too large to read into memory (" + (ec ? std::string("its size unknown") : std::to_string(size) + " bytes") +
                         ", more than this machine or this process's limit, ulimit -v, can hold)");
    }
}

}  // namespace rt
