#include "rt/io/obj_parser.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "rt/core/errors.hpp"
#include "rt/core/printable.hpp"

namespace rt {
namespace {

// One token of a line, and where it starts.
struct Token {
    std::string_view text;
    std::size_t column;  // from 1
};

std::vector<Token> tokens_of(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        if (line[i] == ' ' || line[i] == '\t') {
            ++i;
            continue;
        }
        if (line[i] == '#') break;  // a comment, to the end of the line
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        tokens.push_back({line.substr(start, i - start), start + 1});
    }
    return tokens;
}

std::string show(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

class Reader {
  public:
    Reader(double largest) : largest_(largest) {}

    [[noreturn]] void fail(std::size_t column, const std::string& what) const {
        throw InputError("line " + std::to_string(line_) + ", column " + std::to_string(column) + ": " + what);
    }
    std::string found(const Token& t) const { return "\"" + printable(t.text, 64) + "\""; }

    double number(const Token& t) const {
        std::string_view s = t.text;
        if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
        double x = 0;
        const auto r = std::from_chars(s.data(), s.data() + s.size(), x, std::chars_format::general);
        const std::string expected =
            "must be a finite number of magnitude at most " + show(largest_) + ", got ";
        if (r.ec == std::errc::result_out_of_range) fail(t.column, expected + found(t) + " (beyond a double)");
        if (r.ec != std::errc() || r.ptr != s.data() + s.size()) fail(t.column, expected + found(t));
        if (!std::isfinite(x) || std::abs(x) > largest_) fail(t.column, expected + found(t));
        return x;
    }

    // The statement that gives an item of the list `what` names.
    static const char* keyword_of(std::string_view what) {
        return what == "vertex" ? "v" : what == "normal" ? "vn" : "vt";
    }

    // An index of an OBJ list of `count` items so far ("vertex", "texture coordinate", "normal"): 1..count,
    // or -1..-count counting back. Returns it from 0.
    std::uint32_t index(const Token& t, std::string_view part, std::size_t column, std::size_t count,
                        const char* what) const {
        const std::string range = "[1, " + std::to_string(count) + "]";
        const std::string expected = std::string(what) + " index must be a whole number in " + range +
                                     " (or negative, counting back from the last), got ";
        long long value = 0;
        const auto r = std::from_chars(part.data(), part.data() + part.size(), value);
        const Token shown_part{part, column};
        if (part.empty()) fail(column, expected + "nothing (in " + found(t) + ")");
        if (count == 0) {
            fail(column, std::string(what) + " index " + found(shown_part) + " refers to a " +
                             keyword_of(what) + " line, but none comes before it");
        }
        if (r.ec == std::errc::result_out_of_range) fail(column, expected + found(shown_part));
        if (r.ec != std::errc() || r.ptr != part.data() + part.size() || part[0] == '+')
            fail(column, expected + found(shown_part));
        const long long n = (long long)(count);
        if (value == 0 || value > n || value < -n) fail(column, expected + found(shown_part));
        return std::uint32_t(value > 0 ? value - 1 : n + value);
    }

    void vertex(const std::vector<Token>& tokens, ObjMesh& mesh) {
        const std::size_t numbers = tokens.size() - 1;
        if (numbers != 3 && numbers != 4 && numbers != 6) {
            fail(tokens[0].column, "a vertex must have 3 coordinates x y z (then w, or r g b), got " +
                                       std::to_string(numbers) + " number(s)");
        }
        double xyz[3];
        for (std::size_t i = 1; i < tokens.size(); ++i) {
            const double x = number(tokens[i]);
            if (i <= 3) xyz[i - 1] = x;
        }
        mesh.positions.push_back(Vec3(Real(xyz[0]), Real(xyz[1]), Real(xyz[2])));
    }

    std::vector<double> numbers(const std::vector<Token>& tokens, std::size_t low, std::size_t high,
                                const char* what) const {
        const std::size_t n = tokens.size() - 1;
        if (n < low || n > high) {
            fail(tokens[0].column, std::string("a ") + what + " must have " + std::to_string(low) +
                                       (low == high ? "" : " to " + std::to_string(high)) + " numbers, got " +
                                       std::to_string(n));
        }
        std::vector<double> values;
        for (std::size_t i = 1; i < tokens.size(); ++i) values.push_back(number(tokens[i]));
        return values;
    }

    void texture_coordinate(const std::vector<Token>& tokens, ObjMesh& mesh) const {
        const std::vector<double> uvw = numbers(tokens, 1, 3, "texture coordinate (vt)");
        mesh.texture_coordinates.push_back(Vec2(Real(uvw[0]), Real(uvw.size() > 1 ? uvw[1] : 0)));
    }

    void normal(const std::vector<Token>& tokens, ObjMesh& mesh) const {
        const std::vector<double> n = numbers(tokens, 3, 3, "normal (vn)");
        const Vec3 v{Real(n[0]), Real(n[1]), Real(n[2])};
        if (!(glm::dot(v, v) > 0))
            fail(tokens[1].column, "a normal (vn) must not be zero (or so small its square is)");
        mesh.normals.push_back(v);
    }

    // Whether corner k of a face gives an attribute, against the face's first corner: all or none.
    void same_as_first(const Token& t, std::size_t corner, bool given, bool first_given,
                       const char* what) const {
        if (corner > 0 && given != first_given) {
            fail(t.column,
                 std::string("a face gives a ") + what + " at every corner or at none; corner " + found(t) +
                     (given ? " gives one and the first does not" : " gives none and the first does"));
        }
    }

    // A face's corners: vertex indices resolved now (a negative one counts back from here; a positive one is
    // checked at the end, against every vertex of the file).
    void face(const std::vector<Token>& tokens, ObjMesh& mesh) {
        if (tokens.size() < 4) {
            fail(tokens[0].column,
                 "a face must have at least 3 vertices, got " + std::to_string(tokens.size() - 1));
        }
        ObjFace f{{}, {}, {}, line_};
        for (std::size_t i = 1; i < tokens.size(); ++i) {
            const Token& t = tokens[i];
            const std::string_view text = t.text;
            const std::size_t slash = text.find('/');
            const std::string_view v = text.substr(0, slash);
            if (!v.empty() && v[0] != '-') {
                // Checked once every vertex is known: keep the index and where it was.
                long long value = 0;
                const auto r = std::from_chars(v.data(), v.data() + v.size(), value);
                if (r.ec != std::errc() || r.ptr != v.data() + v.size() || value <= 0 ||
                    value > (long long)(UINT32_MAX)) {
                    index(t, v, t.column, mesh.positions.size(), "vertex");  // fails, saying why
                }
                pending_.push_back({mesh.faces.size(), f.vertices.size(), line_, t.column, std::string(v)});
                f.vertices.push_back(std::uint32_t(value - 1));
            } else {
                f.vertices.push_back(index(t, v, t.column, mesh.positions.size(), "vertex"));
            }
            const std::size_t corner = i - 1;
            const std::string_view rest = slash == std::string_view::npos ? "" : text.substr(slash + 1);
            const std::size_t second = rest.find('/');
            const std::string_view vt = rest.substr(0, second);
            const std::size_t vt_column = t.column + slash + 1;
            const bool has_vt =
                slash != std::string_view::npos && (second == std::string_view::npos || !vt.empty());
            same_as_first(t, corner, has_vt, !f.texture_coordinates.empty(), "texture coordinate");
            if (has_vt) {
                f.texture_coordinates.push_back(
                    index(t, vt, vt_column, mesh.texture_coordinates.size(), "texture coordinate"));
            }
            const bool has_vn = slash != std::string_view::npos && second != std::string_view::npos;
            same_as_first(t, corner, has_vn, !f.normals.empty(), "normal");
            if (!has_vn) continue;
            const std::string_view vn = rest.substr(second + 1);
            if (vn.find('/') != std::string_view::npos) fail(t.column, "a face corner has at most 3 parts, got " + found(t));
            f.normals.push_back(index(t, vn, vt_column + second + 1, mesh.normals.size(), "normal"));
        }
        mesh.faces.push_back(std::move(f));
    }

    ObjMesh read(std::string_view text) {
        ObjMesh mesh;
        if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte order mark
        std::size_t start = 0;
        while (start <= text.size()) {
            ++line_;
            std::size_t end = text.find('\n', start);
            if (end == std::string_view::npos) end = text.size();
            std::string_view line = text.substr(start, end - start);
            if (line.ends_with('\r')) line.remove_suffix(1);
            start = end + 1;
            const std::vector<Token> tokens = tokens_of(line);
            if (tokens.empty()) continue;
            const std::string_view keyword = tokens[0].text;
            if (keyword == "v") {
                vertex(tokens, mesh);
            } else if (keyword == "vt") {
                texture_coordinate(tokens, mesh);
            } else if (keyword == "vn") {
                normal(tokens, mesh);
            } else if (keyword == "f") {
                face(tokens, mesh);
            } else if (keyword != "o" && keyword != "g" && keyword != "s" && keyword != "usemtl" &&
                       keyword != "mtllib" && keyword != "l" && keyword != "p") {
                fail(tokens[0].column, "unknown statement " + found(tokens[0]) +
                                           "; expected v, vt, vn, f, o, g, s, usemtl, mtllib, l or p");
            }
        }
        // A mesh is smooth (or textured) everywhere or nowhere: every face as the first one.
        for (const ObjFace& f : mesh.faces) {
            const ObjFace& first = mesh.faces.front();
            for (const auto& [has, first_has, what] :
                 {std::tuple(!f.texture_coordinates.empty(), !first.texture_coordinates.empty(),
                             "texture coordinates (vt)"),
                  std::tuple(!f.normals.empty(), !first.normals.empty(), "normals (vn)")}) {
                if (has == first_has) continue;
                line_ = f.line;
                fail(1, std::string("a mesh gives ") + what + " at every face or at none; this face " +
                            (has ? "gives them" : "does not") + ", the first (line " +
                            std::to_string(first.line) + ") " + (first_has ? "does" : "does not"));
            }
        }
        for (const Pending& p : pending_) {
            line_ = p.line;
            const Token t{p.text, p.column};
            const std::uint32_t i = index(t, t.text, p.column, mesh.positions.size(), "vertex");
            mesh.faces[p.face].vertices[p.corner] = i;
        }
        return mesh;
    }

  private:
    struct Pending {
        std::size_t face, corner, line, column;
        std::string text;
    };
    double largest_;
    std::size_t line_ = 0;
    std::vector<Pending> pending_;
};

}  // namespace

ObjMesh parse_obj(std::string_view text, double largest_coordinate) {
    return Reader(largest_coordinate).read(text);
}

}  // namespace rt
