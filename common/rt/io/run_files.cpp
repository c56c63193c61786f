#include "rt/io/run_files.hpp"

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/io/image_io.hpp"

namespace rt {
namespace fs = std::filesystem;

bool same_file(const fs::path& a, const fs::path& b) {
    // Made absolute first: a relative path with no part that exists stays relative in weakly_canonical.
    std::error_code ec_a, ec_b;
    const fs::path canonical_a = fs::weakly_canonical(fs::absolute(a), ec_a);
    const fs::path canonical_b = fs::weakly_canonical(fs::absolute(b), ec_b);
    if (!ec_a && !ec_b && canonical_a == canonical_b) return true;
    std::error_code ec;
    return fs::equivalent(a, b, ec);
}

void check_files_apart(const std::vector<RunFile>& outputs, const std::vector<RunFile>& inputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const RunFile& out = outputs[i];
        const auto refuse = [&](const RunFile& other, const char* consequence) {
            throw InputError(out.flag + ": " + out.what + " " + shown(out.path) + " is " + other.what + " " +
                             shown(other.path) + ": " + consequence + "; give another name");
        };
        for (const RunFile& in : inputs) {
            if (same_file(out.path, in.path)) refuse(in, "it would be replaced");
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (same_file(out.path, outputs[j].path)) refuse(outputs[j], "one would replace the other");
        }
    }
}

void check_outputs(const std::vector<RunFile>& outputs, const std::vector<RunFile>& inputs) {
    check_files_apart(outputs, inputs);
    for (const RunFile& out : outputs) {
        try {
            check_writable(out.path);
        } catch (const InputError& e) {
            throw InputError(out.flag + ": " + e.what());
        }
    }
}

}  // namespace rt
