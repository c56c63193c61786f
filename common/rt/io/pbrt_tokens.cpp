#include "rt/io/pbrt_tokens.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"

namespace rt {
namespace {

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

bool starts_number(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
}

class Tokenizer {
  public:
    Tokenizer(std::string_view text, const std::string& place) : text_(text), place_(place) {}

    std::vector<PbrtToken> run() {
        std::vector<PbrtToken> tokens;
        while (true) {
            skip_space_and_comments();
            if (at_ >= text_.size()) return tokens;
            PbrtToken token;
            token.line = line_;
            token.column = int(at_ - line_start_) + 1;
            const char c = text_[at_];
            if (c == '[' || c == ']') {
                token.kind = c == '[' ? PbrtTokenKind::kOpen : PbrtTokenKind::kClose;
                token.text = std::string(1, c);
                ++at_;
            } else if (c == '"') {
                token.kind = PbrtTokenKind::kString;
                token.text = quoted(token);
            } else {
                token.text = std::string(bare_word());
                if (starts_number(c)) {
                    token.kind = PbrtTokenKind::kNumber;
                    token.number = number(token);
                }
            }
            tokens.push_back(std::move(token));
        }
    }

  private:
    [[noreturn]] void fail(const PbrtToken& token, const std::string& what) const {
        throw InputError(pbrt_location(place_, token) + what);
    }

    void skip_space_and_comments() {
        while (at_ < text_.size()) {
            const char c = text_[at_];
            if (c == '#') {
                while (at_ < text_.size() && text_[at_] != '\n') ++at_;
            } else if (is_space(c)) {
                if (c == '\n') {
                    ++line_;
                    line_start_ = at_ + 1;
                }
                ++at_;
            } else {
                return;
            }
        }
    }

    std::string_view bare_word() {
        const std::size_t start = at_;
        while (at_ < text_.size() && !is_space(text_[at_]) && text_[at_] != '"' && text_[at_] != '[' &&
               text_[at_] != ']' && text_[at_] != '#') {
            ++at_;
        }
        return text_.substr(start, at_ - start);
    }

    // A quoted string; pbrt's escapes \n \t \\ \" (and \b \f \r).
    std::string quoted(const PbrtToken& token) {
        std::string s;
        ++at_;
        while (true) {
            if (at_ >= text_.size()) fail(token, "string not closed: a \" is missing before the end of the file");
            const char c = text_[at_++];
            if (c == '"') break;
            if (c == '\n') fail(token, "string not closed: a \" is missing before the end of the line");
            if (c != '\\') {
                s += c;
                continue;
            }
            if (at_ >= text_.size()) fail(token, "string not closed: a \" is missing before the end of the file");
            const char e = text_[at_++];
            const std::string_view from = "ntbfr\\\"", to = "\n\t\b\f\r\\\"";
            const std::size_t k = from.find(e);
            if (k == std::string_view::npos) fail(token, "unknown escape \\" + printable(std::string(1, e)) + " in a string");
            s += to[k];
        }
        if (printable(s) != s) {
            fail(token, "a string must be printable UTF-8 text, got \"" + printable(s, 64) + "\"");
        }
        return s;
    }

    double number(const PbrtToken& token) const {
        const std::string& w = token.text;
        double x = 0;
        const char* begin = w.data() + (w[0] == '+' ? 1 : 0);
        const auto [end, error] = std::from_chars(begin, w.data() + w.size(), x);
        if (error == std::errc::result_out_of_range) fail(token, "number out of range: " + printable(w, 64));
        if (error != std::errc() || end != w.data() + w.size() || !std::isfinite(x)) {
            fail(token, "not a number: " + printable(w, 64));
        }
        return x;
    }

    std::string_view text_;
    const std::string& place_;
    std::size_t at_ = 0;
    std::size_t line_start_ = 0;
    int line_ = 1;
};

}  // namespace

std::vector<PbrtToken> tokenize_pbrt(std::string_view text, const std::string& place) {
    return Tokenizer(text, place).run();
}

std::string pbrt_location(const std::string& place, const PbrtToken& token) {
    return place + ":" + std::to_string(token.line) + ":" + std::to_string(token.column) + ": ";
}

}  // namespace rt
