#include "rt/io/json_reader.hpp"

#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"

namespace rt {
namespace {

using Json = nlohmann::json;

// Walks the text for nlohmann's parser, leaving where it is in `*at`: the parser reports a key once it has
// read the key's closing quote, so `*at` then points just past it.
struct TrackedIterator {
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    const char* p;
    const char** at;

    reference operator*() const { return *p; }
    TrackedIterator& operator++() {
        *at = ++p;
        return *this;
    }
    TrackedIterator operator++(int) {
        TrackedIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const TrackedIterator& other) const { return p == other.p; }
};

// "line L, column C" of a byte of the text (both from 1).
std::string place_of(std::string_view text, std::size_t offset) {
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') ++line, line_start = i + 1;
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(offset - line_start + 1);
}

// nlohmann's message without its "[json.exception.parse_error.101] " tag, with the token it last read cut
// to 64 bytes (a string of a megabyte would otherwise be quoted whole), escaped to stay one line.
std::string parse_error_message(std::string what) {
    if (const auto at = what.find("] "); what.starts_with("[json.exception") && at != std::string::npos) {
        what = what.substr(at + 2);
    }
    const std::string marker = "last read: '";
    if (const auto start = what.find(marker); start != std::string::npos) {
        const auto token_start = start + marker.size();
        auto token_end = what.find("'; ", token_start);
        if (token_end == std::string::npos) token_end = what.ends_with('\'') ? what.size() - 1 : what.size();
        const auto length = token_end - token_start;
        if (length > 64) what.replace(token_start, length, what.substr(token_start, 64) + "...");
    }
    return printable(what);
}

// nlohmann's own DOM builder, with every event passed on, and the keys of each open object remembered.
class StrictBuilder {
  public:
    using Dom = nlohmann::detail::json_sax_dom_parser<Json>;

    StrictBuilder(Json& root, std::string_view text, const char** at) : dom_(root, true), text_(text), at_(at) {}

    bool null() { return value(), dom_.null(); }
    bool boolean(bool v) { return value(), dom_.boolean(v); }
    bool number_integer(Json::number_integer_t v) { return value(), dom_.number_integer(v); }
    bool number_unsigned(Json::number_unsigned_t v) { return value(), dom_.number_unsigned(v); }
    bool number_float(Json::number_float_t v, const std::string& s) { return value(), dom_.number_float(v, s); }
    bool string(std::string& v) { return value(), dom_.string(v); }
    bool binary(Json::binary_t& v) { return value(), dom_.binary(v); }
    bool start_object(std::size_t n) { return open(true), dom_.start_object(n); }
    bool end_object() { return frames_.pop_back(), dom_.end_object(); }
    bool start_array(std::size_t n) { return open(false), dom_.start_array(n); }
    bool end_array() { return frames_.pop_back(), dom_.end_array(); }
    bool key(std::string& k) {
        Frame& f = frames_.back();
        const std::size_t here = key_start();
        const auto [first, inserted] = f.keys.emplace(k, here);
        if (!inserted) {
            const std::string place = path();
            throw InputError((place.empty() ? "" : place + ": ") + "key \"" + printable(k, 64) +
                             "\" given twice, at " + place_of(text_, first->second) + " and " +
                             place_of(text_, here));
        }
        f.key = k;
        return dom_.key(k);
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
        throw InputError("not valid JSON: " + parse_error_message(e.what()));
    }

  private:
    struct Frame {
        bool object;
        std::map<std::string, std::size_t> keys;  // each key and where it starts
        std::string key;                          // the key being read (objects)
        std::size_t next = 0;                     // the next element's index (arrays)
    };

    // A value starts: in an array, it is the next element.
    void value() {
        if (!frames_.empty() && !frames_.back().object) ++frames_.back().next;
    }
    // An object or an array starts: a value, then a frame of its own.
    void open(bool object) {
        value();
        frames_.push_back({object, {}, "", 0});
    }
    // The place of the object being read, as the scene loader names places: "shapes[2].transform".
    std::string path() const {
        std::string out;
        for (std::size_t i = 0; i + 1 < frames_.size(); ++i) {
            const Frame& f = frames_[i];
            if (f.object) {
                out += (out.empty() ? "" : ".") + printable(f.key, 64);
            } else {
                out += "[" + std::to_string(f.next - 1) + "]";
            }
        }
        return out;
    }
    // Where the key just read starts: its opening quote, the last unescaped quote before its closing one.
    std::size_t key_start() const {
        std::size_t close = std::size_t(*at_ - text_.data()) - 1;
        for (std::size_t i = close; i-- > 0;) {
            if (text_[i] != '"') continue;
            std::size_t backslashes = 0;
            while (i >= backslashes + 1 && text_[i - backslashes - 1] == '\\') ++backslashes;
            if (backslashes % 2 == 0) return i;
        }
        return close;
    }

    Dom dom_;
    std::string_view text_;
    const char** at_;
    std::vector<Frame> frames_;
};

}  // namespace

Json parse_json_strictly(std::string_view text) {
    Json root;
    const char* at = text.data();
    StrictBuilder builder(root, text, &at);
    Json::sax_parse(TrackedIterator{text.data(), &at}, TrackedIterator{text.data() + text.size(), &at}, &builder);
    return root;
}

}  // namespace rt
