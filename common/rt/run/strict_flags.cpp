#include "rt/run/strict_flags.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"
#include "rt/core/whole_number.hpp"

namespace rt {
namespace {

constexpr double kLargestFlagNumber = 1e30;

}  // namespace

CLI::Validator power_of_two() {
    auto check = [](const std::string& text) -> std::string {
        const std::uint64_t value = std::stoull(text);  // read strictly before this check
        return value > 0 && (value & (value - 1)) == 0 ? "" : "must be a power of two (1, 2, 4, ...), got " + text;
    };
    return CLI::Validator(check, "POWER OF 2");
}

namespace {

std::string check_real(const std::string& text) {
    const char* last = text.data() + text.size();
    double value = 0;
    const auto r = std::from_chars(text.data(), last, value, std::chars_format::general);
    const std::string expected = "a finite decimal number of magnitude at most 1e30";
    if (r.ec != std::errc() || r.ptr != last || text.empty()) {
        return "must be " + expected + ", got " + shown_value(text);
    }
    if (!std::isfinite(value) || std::abs(value) > kLargestFlagNumber) {
        return "must be " + expected + ", got " + shown_value(text);
    }
    return "";
}

}  // namespace

void make_values_strict(CLI::App& app) {
    for (CLI::Option* option : app.get_options()) {
        if (option->get_type_size() == 0) continue;  // a flag without a value
        const std::string type = option->get_type_name();
        std::function<std::string(std::string&)> check;
        if (type.starts_with("UINT")) {
            check = [](std::string& text) { return whole_number_error(text, false); };
        } else if (type.starts_with("INT")) {
            check = [](std::string& text) { return whole_number_error(text, true); };
        } else if (type.starts_with("FLOAT")) {
            check = [](std::string& text) { return check_real(text); };
        } else {
            check = [](std::string& text) { return text.empty() ? std::string("must not be empty") : std::string(); };
        }
        option->transform(CLI::Validator(check, ""), "STRICT");
    }
}

std::optional<int> parse_strictly(CLI::App& app, int argc, char** argv) {
    make_values_strict(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        throw InputError(std::string("usage: ") + e.what() + " (see --help)");
    }
    return std::nullopt;
}

std::optional<int> read_flags(CLI::App& app, int argc, char** argv) {
    try {
        return parse_strictly(app, argc, argv);
    } catch (const InputError& e) {
        const std::string program = std::filesystem::path(argc > 0 ? argv[0] : "").filename().string();
        std::fprintf(stderr, "%s: %s\n", program.c_str(), printable(e.what()).c_str());
        return kExitBadInput;
    }
}

}  // namespace rt
