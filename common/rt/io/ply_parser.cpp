#include "rt/io/ply_parser.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"

namespace rt {
namespace {

enum class Format { kAscii, kBinaryLittleEndian, kBinaryBigEndian };
enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

struct TypeName {
    std::string_view name;
    Type type;
};
constexpr std::array<TypeName, 16> kTypeNames = {{{"char", Type::kInt8},
                                                  {"int8", Type::kInt8},
                                                  {"uchar", Type::kUint8},
                                                  {"uint8", Type::kUint8},
                                                  {"short", Type::kInt16},
                                                  {"int16", Type::kInt16},
                                                  {"ushort", Type::kUint16},
                                                  {"uint16", Type::kUint16},
                                                  {"int", Type::kInt32},
                                                  {"int32", Type::kInt32},
                                                  {"uint", Type::kUint32},
                                                  {"uint32", Type::kUint32},
                                                  {"float", Type::kFloat32},
                                                  {"float32", Type::kFloat32},
                                                  {"double", Type::kFloat64},
                                                  {"float64", Type::kFloat64}}};

std::size_t size_of(Type t) {
    constexpr std::array<std::size_t, 8> kSizes = {1, 1, 2, 2, 4, 4, 4, 8};
    return kSizes[std::size_t(t)];
}
bool is_integer(Type t) {
    return t != Type::kFloat32 && t != Type::kFloat64;
}

// The values an integer type holds.
std::pair<long long, long long> integer_range(Type t) {
    const int bits = int(8 * size_of(t));
    const bool is_signed = t == Type::kInt8 || t == Type::kInt16 || t == Type::kInt32;
    if (is_signed) return {-(1ll << (bits - 1)), (1ll << (bits - 1)) - 1};
    return {0, (1ll << bits) - 1};
}

struct Property {
    std::string name;
    Type type;
    std::optional<Type> count_type;  // a list: its length's type first, then that many of `type`
};

struct Element {
    std::string name;
    std::uint64_t count;
    std::vector<Property> properties;
};

// What the mesh reads of an element's properties: the index of each, or none.
struct VertexLayout {
    std::optional<std::size_t> x, y, z, nx, ny, nz, u, v;
};

// The shortest text that reads back as x: 4294967295 as it is, not as 4.29497e+09.
std::string show(double x) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        if (line[i] == ' ' || line[i] == '\t') {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        words.push_back(line.substr(start, i - start));
    }
    return words;
}

// The data after the header, one value at a time: ASCII words line by line, or binary bytes in the file's
// order. Each error is prefixed with the place.
class Data {
  public:
    Data(Format format, std::string_view bytes, std::size_t line)
        : format_(format), bytes_(bytes), line_(line) {}

    [[noreturn]] void fail(const std::string& what) const {
        const std::string element = where_.empty() ? "" : where_ + ": ";
        if (format_ == Format::kAscii)
            throw InputError("line " + std::to_string(line_) + ": " + element + what);
        const std::string offset = "byte offset " + std::to_string(item_offset_);
        throw InputError(where_.empty() ? offset + ": " + what : where_ + " (" + offset + "): " + what);
    }

    // Starts element `name` number `index`: an ASCII line of its own.
    void begin(const std::string& name, std::uint64_t index) {
        where_ = "element " + name + " " + std::to_string(index);
        item_offset_ = offset_;
        if (format_ != Format::kAscii) return;
        words_.clear();
        next_word_ = 0;
        while (words_.empty()) {
            ++line_;
            if (offset_ >= bytes_.size()) fail("the file ends before it (the header counts more)");
            std::size_t end = bytes_.find('\n', offset_);
            if (end == std::string_view::npos) end = bytes_.size();
            std::string_view line = bytes_.substr(offset_, end - offset_);
            if (line.ends_with('\r')) line.remove_suffix(1);
            offset_ = end + 1;
            words_ = words_of(line);
        }
    }
    // Ends the element: an ASCII line must hold nothing more.
    void end() {
        if (format_ == Format::kAscii && next_word_ < words_.size()) {
            fail("has " + std::to_string(words_.size()) + " values, more than its properties read (" +
                 std::to_string(next_word_) + ")");
        }
    }
    // After the last element: nothing but (ASCII) blank lines.
    void finish() {
        where_.clear();
        if (format_ == Format::kAscii) {
            std::size_t line = line_ + 1;  // the line after the last element's
            for (; offset_ < bytes_.size(); ++offset_) {
                const char c = bytes_[offset_];
                if (c == '\n') ++line;
                if (c != ' ' && c != '\t' && c != '\r' && c != '\n') {
                    line_ = line;
                    fail("data after the last element: the header's counts do not match the data");
                }
            }
        } else if (offset_ != bytes_.size()) {
            item_offset_ = offset_;
            fail(std::to_string(bytes_.size() - offset_) +
                 " byte(s) after the last element: the header's counts do not match the data");
        }
    }
    // Whether `count` more elements of at least `least` bytes each can fit in what is left (binary only).
    bool can_hold(std::uint64_t count, std::size_t least) const {
        return format_ == Format::kAscii ||
               count <= (bytes_.size() - offset_) / std::max<std::size_t>(least, 1);
    }

    double value(Type type, const std::string& what) {
        if (format_ == Format::kAscii) return ascii_value(type, what);
        const std::size_t n = size_of(type);
        if (bytes_.size() - offset_ < n)
            fail(what + ": the file ends inside it (the header counts more data)");
        std::uint64_t bits = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const auto byte = std::uint64_t(std::uint8_t(bytes_[offset_ + i]));
            bits |= byte << (8 * (format_ == Format::kBinaryLittleEndian ? i : n - 1 - i));
        }
        offset_ += n;
        switch (type) {
            case Type::kInt8:
                return double(std::int8_t(bits));
            case Type::kUint8:
                return double(std::uint8_t(bits));
            case Type::kInt16:
                return double(std::int16_t(bits));
            case Type::kUint16:
                return double(std::uint16_t(bits));
            case Type::kInt32:
                return double(std::int32_t(bits));
            case Type::kUint32:
                return double(std::uint32_t(bits));
            case Type::kFloat32:
                return double(std::bit_cast<float>(std::uint32_t(bits)));
            case Type::kFloat64:
                return std::bit_cast<double>(bits);
        }
        return 0;
    }

  private:
    double ascii_value(Type type, const std::string& what) {
        if (next_word_ >= words_.size()) {
            fail("has " + std::to_string(words_.size()) + " values, too few for its properties (" + what +
                 " is missing)");
        }
        std::string_view word = words_[next_word_++];
        const std::string got = "\"" + printable(word, 64) + "\"";
        if (is_integer(type)) {
            long long x = 0;
            const auto r = std::from_chars(word.data(), word.data() + word.size(), x);
            const auto [low, high] = integer_range(type);
            if (r.ec != std::errc() || r.ptr != word.data() + word.size() || x < low || x > high) {
                fail(what + ": must be a whole number in [" + std::to_string(low) + ", " +
                     std::to_string(high) + "], got " + got);
            }
            return double(x);
        }
        if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
        double x = 0;
        const auto r = std::from_chars(word.data(), word.data() + word.size(), x, std::chars_format::general);
        if (r.ec != std::errc() || r.ptr != word.data() + word.size())
            fail(what + ": must be a number, got " + got);
        return x;
    }

    Format format_;
    std::string_view bytes_;
    std::size_t offset_ = 0;       // the next byte to read
    std::size_t item_offset_ = 0;  // where the element began
    std::size_t line_;             // the last line read (ASCII)
    std::string where_;            // "element vertex 12"
    std::vector<std::string_view> words_;
    std::size_t next_word_ = 0;
};

class Reader {
  public:
    explicit Reader(double largest) : largest_(largest) {}

    PlyMesh read(std::string_view bytes) {
        const std::size_t data_start = header(bytes);
        Data data(format_, bytes.substr(data_start), line_);
        PlyMesh mesh;
        for (const Element& e : elements_) {
            std::size_t least = 0;  // bytes per element, at least (a list of length 0)
            for (const Property& p : e.properties) least += size_of(p.count_type ? *p.count_type : p.type);
            if (!data.can_hold(e.count, least)) {
                throw InputError("element " + e.name + ": the header counts " + std::to_string(e.count) +
                                 ", more than the rest of the file can hold");
            }
            reserve(mesh, e);
            for (std::uint64_t i = 0; i < e.count; ++i) {
                data.begin(e.name, i);
                if (e.name == "vertex") {
                    vertex(data, e, mesh);
                } else if (e.name == "face") {
                    face(data, e, mesh);
                } else {
                    for (const Property& p : e.properties) skip(data, p);
                }
                data.end();
            }
        }
        data.finish();
        return mesh;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError("line " + std::to_string(line_) + ": " + what);
    }

    // Reads the header; returns where the data starts.
    std::size_t header(std::string_view bytes) {
        std::size_t start = 0;
        bool ended = false;
        while (!ended) {
            if (start >= bytes.size()) {
                line_ = std::max<std::size_t>(line_, 1);  // the last line, or line 1 of an empty file
                fail("the header has no end_header line");
            }
            ++line_;
            std::size_t end = bytes.find('\n', start);
            if (end == std::string_view::npos) end = bytes.size();
            std::string_view line = bytes.substr(start, end - start);
            if (line.ends_with('\r')) line.remove_suffix(1);
            start = end + 1;
            const std::vector<std::string_view> words = words_of(line);
            if (line_ == 1) {
                if (line != "ply")
                    fail("a PLY file starts with the line \"ply\", got \"" + printable(line, 64) + "\"");
                continue;
            }
            if (words.empty()) fail("a header line is empty");
            const std::string_view keyword = words[0];
            if (keyword == "format") {
                format(words);
            } else if (keyword == "element") {
                element(words);
            } else if (keyword == "property") {
                property(words);
            } else if (keyword == "end_header") {
                ended = true;
            } else if (keyword != "comment" && keyword != "obj_info") {
                fail("unknown header line \"" + printable(keyword, 64) +
                     "\"; expected format, element, property, comment, obj_info or end_header");
            }
        }
        if (!format_known_) fail("the header ends without a format line");
        layout();
        return std::min(start, bytes.size());
    }

    void format(const std::vector<std::string_view>& words) {
        if (format_known_) fail("a second format line");
        if (words.size() != 3 || words[2] != "1.0") fail("a format line is \"format <kind> 1.0\"");
        if (words[1] == "ascii") {
            format_ = Format::kAscii;
        } else if (words[1] == "binary_little_endian") {
            format_ = Format::kBinaryLittleEndian;
        } else if (words[1] == "binary_big_endian") {
            format_ = Format::kBinaryBigEndian;
        } else {
            fail("unknown format \"" + printable(words[1], 64) +
                 "\"; expected ascii, binary_little_endian or binary_big_endian");
        }
        format_known_ = true;
    }

    void element(const std::vector<std::string_view>& words) {
        if (words.size() != 3) fail("an element line is \"element <name> <count>\"");
        std::uint64_t count = 0;
        const auto r = std::from_chars(words[2].data(), words[2].data() + words[2].size(), count);
        if (r.ec != std::errc() || r.ptr != words[2].data() + words[2].size() || count > kMostItems) {
            fail("an element's count must be a whole number in [0, " + std::to_string(kMostItems) +
                 "], got \"" + printable(words[2], 64) + "\"");
        }
        for (const Element& e : elements_) {
            if (e.name == words[1]) fail("a second element \"" + printable(words[1], 64) + "\"");
        }
        if (words[1] == "face" && !has_vertex()) fail("element face must come after element vertex");
        elements_.push_back({std::string(words[1]), count, {}});
    }

    bool has_vertex() const {
        for (const Element& e : elements_) {
            if (e.name == "vertex") return true;
        }
        return false;
    }

    Type type_of(std::string_view name) const {
        for (const TypeName& t : kTypeNames) {
            if (t.name == name) return t.type;
        }
        fail("unknown property type \"" + printable(name, 64) +
             "\"; expected char, uchar, short, ushort, int, uint, float or double (or int8 ... float64)");
    }

    void property(const std::vector<std::string_view>& words) {
        if (elements_.empty()) fail("a property before any element");
        Property p;
        if (words.size() == 5 && words[1] == "list") {
            p.count_type = type_of(words[2]);
            if (!is_integer(*p.count_type)) fail("a list's length type must be an integer type");
            p.type = type_of(words[3]);
            p.name = words[4];
        } else if (words.size() == 3) {
            p.type = type_of(words[1]);
            p.name = words[2];
        } else {
            fail("a property line is \"property <type> <name>\" or \"property list <type> <type> <name>\"");
        }
        for (const Property& q : elements_.back().properties) {
            if (q.name == p.name)
                fail("a second property \"" + p.name + "\" of element " + elements_.back().name);
        }
        elements_.back().properties.push_back(std::move(p));
    }

    // Which properties the mesh reads, checked now: the header's errors are reported at its lines.
    void layout() {
        for (const Element& e : elements_) {
            if (e.name == "vertex") {
                auto find = [&](std::initializer_list<std::string_view> names) -> std::optional<std::size_t> {
                    for (std::size_t i = 0; i < e.properties.size(); ++i) {
                        for (std::string_view name : names) {
                            if (e.properties[i].name == name) {
                                if (e.properties[i].count_type)
                                    fail("vertex property " + e.properties[i].name + " must not be a list");
                                return i;
                            }
                        }
                    }
                    return std::nullopt;
                };
                vertex_ = {find({"x"}),
                           find({"y"}),
                           find({"z"}),
                           find({"nx"}),
                           find({"ny"}),
                           find({"nz"}),
                           find({"u", "s", "texture_u", "texture_s"}),
                           find({"v", "t", "texture_v", "texture_t"})};
                if (!vertex_.x || !vertex_.y || !vertex_.z)
                    fail("element vertex must have properties x, y and z");
                if (bool(vertex_.nx) != bool(vertex_.ny) || bool(vertex_.nx) != bool(vertex_.nz)) {
                    fail("element vertex must have all of nx, ny and nz, or none");
                }
                if (bool(vertex_.u) != bool(vertex_.v))
                    fail("element vertex must have both texture coordinates (u v, s t) or none");
            } else if (e.name == "face") {
                for (std::size_t i = 0; i < e.properties.size(); ++i) {
                    const Property& p = e.properties[i];
                    if (p.name != "vertex_indices" && p.name != "vertex_index") continue;
                    if (!p.count_type || !is_integer(p.type))
                        fail("face property " + p.name + " must be a list of integers");
                    face_indices_ = i;
                }
                if (!face_indices_) fail("element face must have a list property vertex_indices");
            }
        }
        if (!has_vertex()) fail("the header has no element vertex");
    }

    double number(Data& data, const Property& p) const {
        const double x = data.value(p.type, p.name);
        if (!std::isfinite(x) || std::abs(x) > largest_) {
            data.fail(p.name + ": must be a finite number of magnitude at most " + show(largest_) + ", got " +
                      show(x));
        }
        return x;
    }

    void vertex(Data& data, const Element& e, PlyMesh& mesh) const {
        std::vector<double> values(e.properties.size(), 0.0);
        for (std::size_t i = 0; i < e.properties.size(); ++i) {
            if (e.properties[i].count_type) {
                skip(data, e.properties[i]);
            } else {
                values[i] = number(data, e.properties[i]);
            }
        }
        auto at = [&](const std::optional<std::size_t>& i) { return Real(values[*i]); };
        mesh.positions.push_back({at(vertex_.x), at(vertex_.y), at(vertex_.z)});
        if (vertex_.nx) {
            const Vec3 n{at(vertex_.nx), at(vertex_.ny), at(vertex_.nz)};
            if (!(glm::dot(n, n) > 0))
                data.fail("the normal (nx, ny, nz) must not be zero (or so small its square is)");
            mesh.normals.push_back(n);
        }
        if (vertex_.u) mesh.texture_coordinates.push_back({at(vertex_.u), at(vertex_.v)});
    }

    // Room for an element's items, which the file is known to be able to hold (can_hold): a triangle per face.
    void reserve(PlyMesh& mesh, const Element& e) const {
        if (e.name == "vertex") {
            mesh.positions.reserve(e.count);
            if (vertex_.nx) mesh.normals.reserve(e.count);
            if (vertex_.u) mesh.texture_coordinates.reserve(e.count);
        } else if (e.name == "face" && face_indices_) {
            mesh.face_starts.reserve(e.count + 1);
            mesh.corners.reserve(3 * e.count);
        }
    }

    void face(Data& data, const Element& e, PlyMesh& mesh) const {
        for (std::size_t i = 0; i < e.properties.size(); ++i) {
            const Property& p = e.properties[i];
            if (i != face_indices_) {
                skip(data, p);
                continue;
            }
            const double n = data.value(*p.count_type, p.name + "'s length");
            if (!(n >= 3) || n > double(kMostCorners)) {
                data.fail(p.name + ": a face must have 3 to " + std::to_string(kMostCorners) +
                          " vertices, got " + show(n));
            }
            const double vertices = double(mesh.positions.size());
            for (int k = 0; k < int(n); ++k) {
                const double index = data.value(p.type, p.name);
                if (!(index >= 0 && index < vertices)) {
                    data.fail(p.name + ": a vertex index must be in [0, " + show(vertices - 1) + "], got " +
                              show(index));
                }
                mesh.corners.push_back(std::uint32_t(index));
            }
            mesh.face_starts.push_back(mesh.corners.size());
        }
    }

    void skip(Data& data, const Property& p) const {
        if (!p.count_type) {
            data.value(p.type, p.name);
            return;
        }
        const double n = data.value(*p.count_type, p.name + "'s length");
        if (!(n >= 0) || n > double(kMostCorners)) {
            data.fail(p.name + ": a list's length must be in [0, " + std::to_string(kMostCorners) +
                      "], got " + show(n));
        }
        for (int k = 0; k < int(n); ++k) data.value(p.type, p.name);
    }

    static constexpr std::uint64_t kMostItems = std::uint64_t(1) << 31;
    static constexpr int kMostCorners = 1 << 16;
    double largest_;
    std::size_t line_ = 0;
    Format format_ = Format::kAscii;
    bool format_known_ = false;
    std::vector<Element> elements_;
    VertexLayout vertex_;
    std::optional<std::size_t> face_indices_;
};

}  // namespace

PlyMesh parse_ply(std::string_view bytes, double largest_coordinate) {
    return Reader(largest_coordinate).read(bytes);
}

}  // namespace rt
