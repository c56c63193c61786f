// Bad input never crashes and never lies: each broken scene, OBJ, reference image or output path gives an
// InputError whose one line names the file, the place and what was expected. The executables' side of it
// (exit status 2, no output file) is checked by the scripts in tests/cli.
#include <sys/resource.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/core/pixel_sums.hpp"
#include "rt/core/printable.hpp"
#include "rt/core/random.hpp"
#include "rt/io/environment_image.hpp"
#include "rt/io/exr_file.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/obj_parser.hpp"
#include "rt/io/ply_parser.hpp"
#include "rt/io/run_files.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/io/staged_file.hpp"
#include "rt/render/interrupt.hpp"
#include "rt/run/app.hpp"

using namespace rt;
namespace fs = std::filesystem;

namespace {

const fs::path kBadScenes = fs::path(RT_TESTS_DIR) / "data" / "bad_scenes";

// The table tests/data/bad_scenes/expected.tsv: scene file name → the one line its loading must give.
std::map<std::string, std::string> expected_messages() {
    std::ifstream in(kBadScenes / "expected.tsv");
    REQUIRE(in);
    std::map<std::string, std::string> table;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const auto tab = line.find('\t');
        REQUIRE(tab != std::string::npos);
        table[line.substr(0, tab)] = line.substr(tab + 1);
    }
    return table;
}

// Runs `f` with the current folder set to `folder`, so messages show paths as a user typing them would.
template <typename F>
void in_folder(const fs::path& folder, F&& f) {
    const fs::path previous = fs::current_path();
    fs::current_path(folder);
    try {
        f();
    } catch (...) {
        fs::current_path(previous);
        throw;
    }
    fs::current_path(previous);
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "no InputError";
}

fs::path temporary_folder() {
    const fs::path folder = fs::temp_directory_path() / ("rt_bad_input_test_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    return folder;
}

std::string contents(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// What a render of width × height needs: its image of RGB Reals and its exact sums ("326.4 GB" for float at
// 65536²).
std::string gigabytes_of_buffers(double width, double height) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", width * height * double(sizeof(Color) + sizeof(PixelSum)) / 1e9);
    return text;
}

const char* kCamera = R"("camera": {"from": [0, 0, 5], "at": [0, 0, 0]})";

}  // namespace

TEST_CASE("Every bad scene file gives its expected one-line message", "[bad_input]") {
    const auto table = expected_messages();
    std::set<std::string> files;
    for (const auto& entry : fs::directory_iterator(kBadScenes)) {
        const fs::path extension = entry.path().extension();
        if (extension == ".json" || extension == ".pbrt") files.insert(entry.path().filename().string());
    }
    CHECK(files.size() >= 50);
    in_folder(kBadScenes, [&] {
        for (const std::string& file : files) {
            INFO(file);
            const auto row = table.find(file);
            REQUIRE(row != table.end());  // every bad scene has its expected message in expected.tsv
            const std::string message = error_of([&] { load_scene(file); });
            CHECK(message == row->second);
            CHECK(message.find('\n') == std::string::npos);
            // It starts with the file's name (a pbrt file's with its line and column: "bad.pbrt:3:5: ").
            CHECK(message.rfind(file + (file.ends_with(".pbrt") ? ":" : ": "), 0) == 0);
        }
    });
    for (const auto& [file, message] : table) {
        INFO(file);
        CHECK(files.count(file) == 1);  // no row for a file that is not there
    }
}

TEST_CASE("Scenes at the edge of what is allowed still load", "[bad_input]") {
    const std::string camera = kCamera;
    auto sphere = [&](const std::string& center, const std::string& radius) {
        return "{" + camera +
               R"(, "materials": {"w": {"type": "diffuse"}}, "shapes": [{"type": "sphere", "center": )" +
               center + R"(, "radius": )" + radius + R"(, "material": "w"}]})";
    };
    CHECK_NOTHROW(parse_scene(sphere("[1e9, -1e9, 0]", "1e9"), "edge.json"));
    CHECK_NOTHROW(parse_scene(sphere("[0, 0, 0]", "1e-30"), "edge.json"));
    CHECK(error_of([&] { parse_scene(sphere("[1.0000001e9, 0, 0]", "1"), "edge.json"); }) ==
          "edge.json: shapes[0].center[0]: must be a finite number of magnitude at most 1e+09, got 1e+09");
    // An up vector a millionth of a radian from the view direction still gives a camera basis.
    CHECK_NOTHROW(
        parse_scene(R"({"camera": {"from": [0, 0, 0], "at": [0, 0, -1], "up": [1e-6, 0, -1]}})", "e.json"));
    CHECK_NOTHROW(
        parse_scene(R"({"camera": {"from": [0, 0, 0], "at": [0, 0, -1], "vfov": 179.9}})", "e.json"));
}

TEST_CASE("An environment image: OpenEXR refused where the build has no OpenEXR, a negative pixel and a scaled "
          "pixel above 10^9 refused, one of 10^9 loaded",
          "[bad_input]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        { std::ofstream("sky.exr", std::ios::binary) << "not an EXR file"; }
        const std::string exr = error_of([&] {
            parse_scene("{" + std::string(kCamera) + R"(, "lights": [{"type": "environment", "image": "sky.exr"}]})",
                        "e.json");
        });
        if (has_openexr()) {
            CHECK(exr.rfind("e.json: lights[0].image: sky.exr: must be an OpenEXR file it can read (", 0) == 0);
        } else {
            CHECK(exr == "e.json: lights[0].image: sky.exr: OpenEXR images are not read by this build (install "
                         "libopenexr-dev and configure again), or convert it to .hdr or .pfm");
        }
        Image negative(2, 1);
        negative.at(1, 0) = Color(-1, 0, 0);
        write_pfm(negative, "negative.pfm");
        CHECK(error_of([&] {
                  parse_scene("{" + std::string(kCamera) +
                                  R"(, "lights": [{"type": "environment", "image": "negative.pfm"}]})",
                              "e.json");
              }) == "e.json: lights[0].image: negative.pfm: pixel (1, 0) must be finite radiance, >= 0, got -1 0 0");
        Image bright(1, 1);
        bright.at(0, 0) = Color(1e38f);
        write_pfm(bright, "bright.pfm");
        CHECK(error_of([&] {
                  parse_scene("{" + std::string(kCamera) +
                                  R"(, "lights": [{"type": "environment", "image": "bright.pfm", "scale": 1e9}]})",
                              "e.json");
              }) == "e.json: lights[0].scale: 1e+09 makes pixel (0, 0) of the image 1e+47, above 1e+09, the limit of "
                    "every radiance in a scene (as of emission, intensity and radiance), which keeps chapter 11's "
                    "float sums of samples finite");
        Image edge(1, 1);
        edge.at(0, 0) = Color(2e9f, 0, 1);
        write_pfm(edge, "edge.pfm");
        const Scene scene = parse_scene(
            "{" + std::string(kCamera) + R"(, "lights": [{"type": "environment", "image": "edge.pfm", "scale": 0.5}]})",
            "e.json");
        CHECK(scene.environment->radiance.r == 1e9f);
    });
    fs::remove_all(folder);
}

TEST_CASE("A scene's image too large for memory loads: the size refused is the one rendered", "[bad_input]") {
    const std::string text = "{" + std::string(kCamera) + R"(, "image": {"width": 65536, "height": 65536}})";
    CHECK(parse_scene(text, "huge.json").image.width == 65536);
    CHECK_THAT(error_of([] { check_image_size(65536, 65536); }),
               Catch::StartsWith("image size 65536x65536 needs " + gigabytes_of_buffers(65536, 65536) +
                                 " of buffers, more than half of this machine's"));
}

TEST_CASE("Names with control characters are printed escaped, so a message stays one line", "[bad_input]") {
    const std::string text = "{" + std::string(kCamera) + R"(, "bad\nkey\u0001": 1})";
    CHECK(error_of([&] { parse_scene(text, "c.json"); }) == "c.json: bad\\nkey\\x01: unknown key");
}

TEST_CASE("Numbers too large for a double and whole numbers too large for a long are refused",
          "[bad_input]") {
    const std::string camera = kCamera;
    CHECK(error_of([&] {
              parse_scene("{" + camera + R"(, "image": {"width": 18446744073709551615}})", "n.json");
          }) == "n.json: image.width: must be in [1, 65536], got 18446744073709551615");
    CHECK(error_of([&] { parse_scene("{" + camera + R"(, "image": {"spp": -3}})", "n.json"); }) ==
          "n.json: image.spp: must be in [1, 1048576], got -3");
    CHECK(error_of([&] {
              parse_scene(R"({"camera": {"from": [0, 0, -1e999], "at": [0, 0, 0]}})", "n.json");
          }) == "n.json: not valid JSON: number overflow parsing '-1e999'");
}

TEST_CASE("A reference image that is missing, a folder, not PFM, truncated or not finite is refused",
          "[bad_input][image]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        CHECK(error_of([] { read_pfm("absent.pfm"); }) == "absent.pfm: must be a PFM file, got no such file");
        fs::create_directories("folder.pfm");
        CHECK(error_of([] { read_pfm("folder.pfm"); }) == "folder.pfm: must be a PFM file, got a folder");
        fs::create_symlink("loop_b.pfm", "loop_a.pfm");
        fs::create_symlink("loop_a.pfm", "loop_b.pfm");
        CHECK(error_of([] { read_pfm("loop_a.pfm"); }) ==
              "loop_a.pfm: must be a PFM file, got a path that cannot be followed (Too many levels of symbolic "
              "links)");
        std::ofstream("p6.pfm") << "P6\n4 4\n255\n";
        CHECK(error_of([] { read_pfm("p6.pfm"); }) ==
              "p6.pfm: must be a colour PFM file starting with \"PF\", got \"P6\"");
        std::ofstream("zero.pfm") << "PF\n0 4\n-1.0\n";
        CHECK(error_of([] { read_pfm("zero.pfm"); }) ==
              "zero.pfm: PFM header must give a width and height in [1, 65536] and a non-zero scale, got 0 4 -1");
        std::ofstream("big_scale.pfm") << "PF\n0 4\n-1e308\n";
        CHECK(error_of([] { read_pfm("big_scale.pfm"); }) ==
              "big_scale.pfm: PFM header must give a width and height in [1, 65536] and a non-zero scale, got 0 4 "
              "-1e+308");
        // A header that promises 51 GB is refused by the file's size, before anything is allocated.
        std::ofstream("huge.pfm") << "PF\n65536 65536\n-1.0\n" << std::string(100, 'x');
        CHECK(error_of([] { read_pfm("huge.pfm"); }) ==
              "huge.pfm: PFM data must be 51539607552 bytes for 65536x65536, got 100 (truncated)");
        // One pixel of the given value, under the given header.
        auto pfm = [](const char* file, const char* header, float r, float g, float b) {
            std::ofstream out(file, std::ios::binary);
            out << header;
            const float rgb[3] = {r, g, b};
            out.write(reinterpret_cast<const char*>(rgb), sizeof rgb);
        };
        pfm("nan.pfm", "PF\n1 1\n-1.0\n", 0.5f, std::numeric_limits<float>::quiet_NaN(), 1);
        CHECK(error_of([] { read_pfm("nan.pfm"); }) ==
              "nan.pfm: pixel (0, 0) must be finite, got 0.5 nan 1");
        // A reference is radiance: never negative.
        pfm("negative.pfm", "PF\n1 1\n-1.0\n", 0.5f, -0.25f, 1);
        CHECK(read_pfm("negative.pfm").at(0, 0) == Color(0.5f, -0.25f, 1));
        CHECK(error_of([] { read_pfm("negative.pfm", PfmPixels::kRadiance); }) ==
              "negative.pfm: pixel (0, 0) must be finite radiance, >= 0, got 0.5 -0.25 1");
        pfm("minus_1e30.pfm", "PF\n1 1\n-1.0\n", -1e30f, 0, 0);
        CHECK(error_of([] { read_pfm("minus_1e30.pfm", PfmPixels::kRadiance); }) ==
              "minus_1e30.pfm: pixel (0, 0) must be finite radiance, >= 0, got -1.00000002e+30 0 0");
        // A CRLF header would shift every pixel by one byte: it is named, not read as a NaN pixel.
        pfm("crlf.pfm", "PF\r\n1 1\r\n-1.0\r\n", 0.5f, 0.5f, 0.5f);
        CHECK(error_of([] { read_pfm("crlf.pfm"); }) ==
              "crlf.pfm: PFM header must end in one whitespace byte before the pixels, got \"\\r\\n\" (a "
              "Windows line end)");
        pfm("good.pfm", "PF\n1 1\n-1.0\n", 0.5f, 0, 2);
        CHECK(read_pfm("good.pfm").at(0, 0) == Color(0.5f, 0, 2));
    });
    fs::remove_all(folder);
}

TEST_CASE("An output path that cannot be written is refused before anything is written",
          "[bad_input][image]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        std::ofstream("a_file") << "not a folder";
        fs::create_directories("a_folder.png");
        CHECK(error_of([] { check_writable("missing/x.png"); }) ==
              "missing/x.png: cannot be written: folder missing does not exist");
        // Tests run as root here, so a folder without write permission would not stop them: a path whose
        // parent is a regular file cannot be written by anyone.
        CHECK(error_of([] { check_writable("a_file/x.png"); }) ==
              "a_file/x.png: cannot be written: a_file is a file, not a folder");
        CHECK(error_of([] { check_writable("a_folder.png"); }) ==
              "a_folder.png: cannot be written: it is a folder");
        CHECK_THROWS_AS(write_png(Image(2, 2), "a_file/x.png"), InputError);
        CHECK_THROWS_AS(write_pfm(Image(2, 2), "a_folder.png"), InputError);
        CHECK(contents("a_file") == "not a folder");
        CHECK(fs::is_empty("a_folder.png"));
    });
    fs::remove_all(folder);
}

TEST_CASE("A write that fails (file too large) leaves the earlier file as it was and no temporary file",
          "[bad_input][image]") {
    const fs::path folder = temporary_folder();
    Image noise(64, 64);  // 12 KiB of pixels that PNG cannot compress below 1 KiB
    Pcg32 rng(3, 4);
    for (Color& c : noise.pixels()) c = Color(rng.next_real(), rng.next_real(), rng.next_real());
    in_folder(folder, [&] {
        std::ofstream("keep.png") << "earlier png";
        std::ofstream("keep.pfm") << "earlier pfm";
        // As a full disk would: files may grow to 1 KiB, and a write beyond fails (EFBIG, not SIGXFSZ).
        rlimit previous{};
        REQUIRE(getrlimit(RLIMIT_FSIZE, &previous) == 0);
        rlimit small = previous;
        small.rlim_cur = 1024;
        const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
        REQUIRE(setrlimit(RLIMIT_FSIZE, &small) == 0);
        const std::string png_error = [&] {
            try {
                write_png(noise, "keep.png");
            } catch (const std::runtime_error& e) {
                return std::string(e.what());
            }
            return std::string("no error");
        }();
        const std::string pfm_error = [&] {
            try {
                write_pfm(noise, "keep.pfm");
            } catch (const std::runtime_error& e) {
                return std::string(e.what());
            }
            return std::string("no error");
        }();
        setrlimit(RLIMIT_FSIZE, &previous);
        std::signal(SIGXFSZ, previous_handler);
        CHECK(png_error ==
              "keep.png: could not write the file (File too large); an earlier file of that name is left as "
              "it was");
        CHECK(pfm_error ==
              "keep.pfm: could not write the file (File too large); an earlier file of that name is left as "
              "it was");
        CHECK(contents("keep.png") == "earlier png");
        CHECK(contents("keep.pfm") == "earlier pfm");
        for (const auto& entry : fs::directory_iterator(".")) {
            CHECK(entry.path().filename().string().find(".staging") == std::string::npos);
        }
        // Without the limit, the same writes replace the files whole.
        write_pfm(noise, "keep.pfm");
        CHECK(read_pfm("keep.pfm").pixels() == noise.pixels());
    });
    fs::remove_all(folder);
}

namespace {

// Runs rt::run_chapter as a chapter's main would, with `render` standing in for the chapter's render.
int run_fake_chapter(std::vector<std::string> args, const ChapterRender& render) {
    args.insert(args.begin(), "ch00_fake");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    const ChapterInfo chapter{"ch00_fake", "a stand-in chapter for tests", "ch01_default.json",
                              EffectSet{Effect::kCameraRays}};
    return run_chapter(int(argv.size()), argv.data(), chapter, nullptr, render);
}

ChapterRun fake_run(const RunContext& context, Color value, bool interrupted, std::uint64_t samples) {
    ChapterRun run;
    run.result.image = Image(context.settings.width, context.settings.height);
    for (Color& c : run.result.image.pixels()) c = Color(0.5f);
    run.result.image.at(1, 1) = value;
    run.result.interrupted = interrupted;
    run.result.samples = samples;
    run.result.samples_per_pixel = interrupted ? 0 : context.settings.samples_per_pixel;
    return run;
}

}  // namespace

TEST_CASE("A render with a NaN or infinite pixel is a failure (exit 1) and writes nothing",
          "[bad_input][app]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        const std::vector<std::string> args{"--width", "4", "--height", "3", "--quiet", "--out", "x.png"};
        for (const Real bad :
             {std::numeric_limits<Real>::quiet_NaN(), std::numeric_limits<Real>::infinity()}) {
            CHECK(run_fake_chapter(args, [&](const RunContext& c) {
                      return fake_run(c, Color(0, bad, 0), false, 12);
                  }) == kExitFailure);
            CHECK_FALSE(fs::exists("x.png"));
            CHECK_FALSE(fs::exists("x.pfm"));
        }
        CHECK(run_fake_chapter(args, [&](const RunContext& c) { return fake_run(c, Color(1), false, 12); }) ==
              kExitOk);
        CHECK(read_pfm("x.pfm").at(1, 1) == Color(1));
        CHECK(fs::exists("x.png"));
    });
    fs::remove_all(folder);
}

TEST_CASE(
    "An interrupted render writes NAME.partial.png and .pfm and exits 130, and with no sample writes nothing",
    "[bad_input][app]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        const std::vector<std::string> args{"--width", "4", "--height", "3", "--quiet", "--out", "y.png"};
        CHECK(run_fake_chapter(
                  args, [&](const RunContext& c) { return fake_run(c, Color(0.25f), true, 0); }) == 130);
        CHECK(fs::is_empty("."));
        CHECK(run_fake_chapter(
                  args, [&](const RunContext& c) { return fake_run(c, Color(0.25f), true, 7); }) == 130);
        CHECK(read_pfm("y.partial.pfm").at(1, 1) == Color(0.25f));
        CHECK(fs::exists("y.partial.png"));
        CHECK_FALSE(fs::exists("y.png"));
        CHECK_FALSE(fs::exists("y.pfm"));
    });
    fs::remove_all(folder);
}

TEST_CASE("Bad input found by the chapter itself is exit 2, and nothing is written", "[bad_input][app]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        const std::vector<std::string> args{"--width", "4", "--height", "3", "--quiet", "--out", "z.png"};
        CHECK(run_fake_chapter(args, [](const RunContext&) -> std::optional<ChapterRun> {
                  throw InputError("--demo: must be 1 or 2, got 3");
              }) == kExitBadInput);
        CHECK(
            run_fake_chapter({"--scene", "absent.json"}, [](const RunContext&) -> std::optional<ChapterRun> {
                FAIL("rendered a scene that does not exist");
                return std::nullopt;
            }) == kExitBadInput);
        CHECK(fs::is_empty("."));
    });
    fs::remove_all(folder);
}

TEST_CASE("An OBJ file cannot make the loader open another file through mtllib", "[bad_input]") {
    // Were the material library read, /dev/zero would never end: the loader would hang.
    const fs::path folder = temporary_folder();
    std::ofstream(folder / "m.obj")
        << "mtllib /dev/zero\nmtllib ../../../../../../dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
        << "usemtl nothing\nf 1 2 3\n";
    const Scene scene = parse_scene("{" + std::string(kCamera) + R"(, "materials": {"w": {"type": "diffuse"}},
        "shapes": [{"type": "mesh", "file": "m.obj", "material": "w"}]})",
                                    folder / "m.json");
    CHECK(std::get<MeshShape>(scene.shapes[0].geometry).triangles.size() == 1);
    fs::remove_all(folder);
}

TEST_CASE("Every number of an OBJ file is read strictly, and an error names its line and column",
          "[bad_input][obj]") {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    auto obj_error = [](const std::string& text) { return error_of([&] { parse_obj(text, 1e9); }); };
    const std::string vertex = "must be a finite number of magnitude at most 1e+09, got ";
    CHECK(obj_error(tri + "v nan 0 0\nf 1 2 3\n") == "line 4, column 3: " + vertex + "\"nan\"");
    CHECK(obj_error(tri + "v 0 -inf 0\n") == "line 4, column 5: " + vertex + "\"-inf\"");
    CHECK(obj_error("v abc def ghi\n") == "line 1, column 3: " + vertex + "\"abc\"");
    CHECK(obj_error("v 1 2 3x\n") == "line 1, column 7: " + vertex + "\"3x\"");
    CHECK(obj_error("v 1e400 0 0\n") == "line 1, column 3: " + vertex + "\"1e400\" (beyond a double)");
    CHECK(obj_error("v 0 0 2e9\n") == "line 1, column 7: " + vertex + "\"2e9\"");
    CHECK(obj_error(tri + "v -1 0\n") ==
          "line 4, column 1: a vertex must have 3 coordinates x y z (then w, or r g b), got 2 number(s)");
    const std::string index =
        "vertex index must be a whole number in [1, 3] (or negative, counting back from the last), got ";
    CHECK(obj_error(tri + "f 1 2 3abc\n") == "line 4, column 7: " + index + "\"3abc\"");
    CHECK(obj_error(tri + "f 1 2 3.7\n") == "line 4, column 7: " + index + "\"3.7\"");
    CHECK(obj_error(tri + "f 1 2 4294967299\n") == "line 4, column 7: " + index + "\"4294967299\"");
    CHECK(obj_error(tri + "f 1 2 99999999999999999999\n") ==
          "line 4, column 7: " + index + "\"99999999999999999999\"");
    CHECK(obj_error(tri + "f 1 2 0\n") == "line 4, column 7: " + index + "\"0\"");
    CHECK(obj_error(tri + "f 1 2 -4\n") == "line 4, column 7: " + index + "\"-4\"");
    CHECK(obj_error(tri + "f 1 2 +3\n") == "line 4, column 7: " + index + "\"+3\"");
    CHECK(obj_error(tri + "f 1 2 4\n") == "line 4, column 7: " + index + "\"4\"");  // checked at the end
    CHECK(obj_error(tri + "f 1 2\n") == "line 4, column 1: a face must have at least 3 vertices, got 2");
    CHECK(
        obj_error(tri + "vt 0 0\nf 1/2 2 3\n") ==
        "line 5, column 5: texture coordinate index must be a whole number in [1, 1] (or negative, counting "
        "back from the last), got \"2\"");
    CHECK(obj_error(tri + "vn 0 0 x\n") == "line 4, column 8: " + vertex + "\"x\"");
    CHECK(obj_error(tri + "curv 0 1 2\n") ==
          "line 4, column 1: unknown statement \"curv\"; expected v, vt, vn, f, o, g, s, usemtl, mtllib, l or p");
    CHECK(obj_error("v 0 0 0\n\x01 1 2\n") ==
          "line 2, column 1: unknown statement \"\\x01\"; expected v, vt, vn, f, o, g, s, usemtl, mtllib, l or p");

    // Texture coordinates and normals: at every corner of a face or at none, at every face as at the first,
    // and no zero normal.
    const std::string with_vt_vn = tri + "vt 0 0\nvn 0 0 1\n";
    CHECK(obj_error(with_vt_vn + "f 1/1/1 2//1 3/1/1\n") ==
          "line 6, column 9: a face gives a texture coordinate at every corner or at none; corner \"2//1\" "
          "gives "
          "none and the first does");
    CHECK(obj_error(with_vt_vn + "f 1/1 2/1/1 3/1\n") ==
          "line 6, column 7: a face gives a normal at every corner or at none; corner \"2/1/1\" gives one "
          "and the "
          "first does not");
    CHECK(
        obj_error(with_vt_vn + "f 1//1 2//1 3//1\nf 1 2 3\n") ==
        "line 7, column 1: a mesh gives normals (vn) at every face or at none; this face does not, the first "
        "(line 6) does");
    CHECK(obj_error(tri + "vn 0 0 0\n") ==
          "line 4, column 4: a normal (vn) must not be zero (or so small its square is)");
    CHECK(obj_error(tri + "vn 0 0 1e-30\n") ==
          "line 4, column 4: a normal (vn) must not be zero (or so small its square is)");

    // What is allowed: a byte order mark, CRLF, comments, w and colours, vt (1 to 3 numbers) and vn, every
    // corner form, negative indices, forward references, polygons.
    const ObjMesh m = parse_obj(
        "\xEF\xBB\xBFv 0 0 0 1\r\nv 1 0 0 0.5 0.5 0.5\r\n# a comment\nv 0 1 0 # after a vertex\nvt 0.25 1\n"
        "vn 0 0 2\nvt 0.5\ng part\ns off\nf 1/1/1 2/2/1 -1/1/-1\nf 1/-1/1 2/1/1 3/1/1 4/2/1\nv 1 1 0\n",
        1e9);
    REQUIRE(m.positions.size() == 4);
    REQUIRE(m.faces.size() == 2);
    CHECK(m.faces[0].vertices == std::vector<std::uint32_t>{0, 1, 2});
    CHECK(m.faces[1].vertices == std::vector<std::uint32_t>{0, 1, 2, 3});
    CHECK(m.faces[0].texture_coordinates == std::vector<std::uint32_t>{0, 1, 0});
    CHECK(m.faces[1].texture_coordinates == std::vector<std::uint32_t>{1, 0, 0, 1});
    CHECK(m.faces[0].normals == std::vector<std::uint32_t>{0, 0, 0});
    CHECK(m.faces[1].line == 11);
    CHECK(m.positions[1] == Vec3(1, 0, 0));
    CHECK(m.texture_coordinates == std::vector<Vec2>{{0.25f, 1}, {0.5f, 0}});
    CHECK(m.normals == std::vector<Vec3>{{0, 0, 2}});  // as written: the loader normalises
    // Faces without either, as every OBJ before vn and vt were read.
    const ObjMesh plain = parse_obj(tri + "vt 0 0\nvn 0 0 1\nf 1 2 3\n", 1e9);
    CHECK(plain.faces[0].texture_coordinates.empty());
    CHECK(plain.faces[0].normals.empty());
}

TEST_CASE(
    "A broken PLY file is refused with its place: the header's line, the ASCII line, the binary element",
    "[bad_input][ply]") {
    auto ply_error = [](const std::string& bytes) { return error_of([&] { parse_ply(bytes, 1e9); }); };
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
    CHECK(ply_error(header + vertices + "3 0 1 2\n") == "no InputError");
    CHECK(ply_error("plx\n") == "line 1: a PLY file starts with the line \"ply\", got \"plx\"");
    CHECK(ply_error("ply\nformat ascii 2.0\n") == "line 2: a format line is \"format <kind> 1.0\"");
    CHECK(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n") ==
          "line 5: element vertex must have properties x, y and z");
    CHECK(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n") ==
          "line 4: unknown property type \"quad\"; expected char, uchar, short, ushort, int, uint, float or "
          "double "
          "(or int8 ... float64)");
    CHECK(ply_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n") ==
          "line 4: the header has no end_header line");
    // Counts that do not match the data, both ways.
    CHECK(ply_error(header + vertices) ==
          "line 13: element face 0: the file ends before it (the header counts more)");
    CHECK(ply_error(header + vertices + "3 0 1 2\n3 0 1 2\n") ==
          "line 14: data after the last element: the header's counts do not match the data");
    CHECK(ply_error(header + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n") ==
          "line 11: element vertex 1: has 2 values, too few for its properties (z is missing)");
    CHECK(ply_error(header + "0 0 0 7\n1 0 0\n0 1 0\n3 0 1 2\n") ==
          "line 10: element vertex 0: has 4 values, more than its properties read (3)");
    // Values: finite, within the limits, whole and in range where they are indices.
    CHECK(ply_error(header + "0 0 nan\n1 0 0\n0 1 0\n3 0 1 2\n") ==
          "line 10: element vertex 0: z: must be a finite number of magnitude at most 1e+09, got nan");
    CHECK(ply_error(header + "0 0 2e9\n1 0 0\n0 1 0\n3 0 1 2\n") ==
          "line 10: element vertex 0: z: must be a finite number of magnitude at most 1e+09, got 2e+09");
    CHECK(ply_error(header + vertices + "3 0 1 3\n") ==
          "line 13: element face 0: vertex_indices: a vertex index must be in [0, 2], got 3");
    CHECK(ply_error(header + vertices + "3 0 1 1.5\n") ==
          "line 13: element face 0: vertex_indices: must be a whole number in [-2147483648, 2147483647], got "
          "\"1.5\"");
    CHECK(ply_error(header + vertices + "2 0 1\n") ==
          "line 13: element face 0: vertex_indices: a face must have 3 to 65536 vertices, got 2");
    CHECK(
        ply_error(header + vertices + "300 0 1\n") ==
        "line 13: element face 0: vertex_indices's length: must be a whole number in [0, 255], got \"300\"");
    // Binary: the element and its byte offset.
    std::string binary =
        "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n";
    const std::string zero(12, '\0');
    CHECK(ply_error(binary + zero) == "no InputError");
    CHECK(ply_error(binary + zero.substr(0, 10)) ==
          "element vertex: the header counts 1, more than the rest of the file can hold");
    const std::string with_face =
        "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar uint vertex_indices\nend_header\n";
    CHECK(ply_error(with_face + zero + "\x03" + std::string(4, '\0')) ==
          "element face 0 (byte offset 12): vertex_indices: the file ends inside it (the header counts more "
          "data)");
    CHECK(ply_error(binary + zero + "xy") ==
          "byte offset 12: 2 byte(s) after the last element: the header's counts do not "
          "match the data");
    const std::string nan_z = zero.substr(0, 8) + std::string("\x00\x00\xc0\x7f", 4);
    CHECK(ply_error(binary + nan_z) ==
          "element vertex 0 (byte offset 0): z: must be a finite number of magnitude at "
          "most 1e+09, got nan");
    CHECK(
        ply_error(
            "ply\nformat binary_big_endian 1.0\nelement vertex 4000000000\nproperty float x\nend_header\n") ==
        "line 3: an element's count must be a whole number in [0, 2147483648], got \"4000000000\"");
    CHECK(ply_error("ply\nformat binary_big_endian 1.0\nelement vertex 2000000000\nproperty float "
                    "x\nproperty float y\n"
                    "property float z\nend_header\n") ==
          "element vertex: the header counts 2000000000, more than the rest of the file can hold");
}

TEST_CASE("An OBJ mesh whose every face has no area is refused, as a lone triangle of no area is",
          "[bad_input][obj]") {
    const fs::path folder = temporary_folder();
    std::ofstream(folder / "flat.obj") << "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\nf 1 2 3\nf 2 3 4 1\n";
    std::ofstream(folder / "one_good.obj") << "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 0 1 0\nf 1 2 3\nf 1 2 4\n";
    auto scene = [&](const std::string& obj, const std::string& transform) {
        return "{" + std::string(kCamera) + R"(, "materials": {"w": {"type": "diffuse"}},
            "shapes": [{"type": "mesh", "file": ")" + obj + R"(", "material": "w")" + transform + "}]}";
    };
    CHECK(error_of([&] { parse_scene(scene("flat.obj", ""), folder / "s.json"); }) ==
          shown(folder / "s.json") + ": shapes[0].file: " + shown(folder / "flat.obj") +
              ": must have at least one face with an area, got 3 triangle(s), each with repeated or collinear "
              "vertices");
    CHECK(parse_scene(scene("one_good.obj", ""), folder / "s.json").shapes.size() == 1);
    // Scaled down until float's cross product underflows: no face has an area left.
    CHECK_THAT(error_of([&] { parse_scene(scene("one_good.obj", R"(, "transform": {"scale": 1e-30})"),
                                          folder / "s.json"); }),
               Catch::EndsWith("each with repeated or collinear vertices after the transform"));
    fs::remove_all(folder);
}

TEST_CASE("A key given twice in one object is refused, naming the key and both places", "[bad_input][json]") {
    CHECK(error_of([] {
              parse_scene("{\"camera\": {\"from\": [0, 0, 5], \"at\": [0, 0, 0], \"from\": [1, 0, 5]}}", "d.json");
          }) == "d.json: camera: key \"from\" given twice, at line 1, column 13 and line 1, column 49");
    CHECK(error_of([] {
              parse_scene("{\"camera\": {\"from\": [0, 0, 5], \"at\": [0, 0, 0]},\n \"shapes\": [{}, {\"a\\\"b\": 1,\n"
                          "   \"a\\\"b\": 2}]}",
                          "d.json");
          }) == "d.json: shapes[1]: key \"a\"b\" given twice, at line 2, column 18 and line 3, column 4");
    CHECK(error_of([] { parse_scene("{\"camera\": 1, \"camera\": 2}", "d.json"); }) ==
          "d.json: key \"camera\" given twice, at line 1, column 2 and line 1, column 15");
    // Equal keys in different objects are not duplicates.
    CHECK_NOTHROW(parse_scene(
        "{\"camera\": {\"from\": [0, 0, 5], \"at\": [0, 0, 0]}, \"materials\": {\"a\": {\"type\": \"diffuse\"}, "
        "\"b\": {\"type\": \"diffuse\"}}, \"shapes\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, "
        "\"material\": \"a\"}, {\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"b\"}]}",
        "d.json"));
}

TEST_CASE("Paths in messages are quoted and escaped when they hold anything but plain characters",
          "[bad_input][message]") {
    CHECK(shown("renders/x-1.png") == "renders/x-1.png");
    CHECK(shown("a b.png") == "\"a b.png\"");
    CHECK(shown("a\nb.png") == "\"a\\nb.png\"");
    CHECK(shown("\x1b[31mred.png") == "\"\\x1b[31mred.png\"");
    CHECK(shown("say \"hi\".png") == "\"say \\\"hi\\\".png\"");
    CHECK(shown("") == "\"\"");
    CHECK(error_of([] { check_writable("no\nsuch/x.png"); }) ==
          "\"no\\nsuch/x.png\": cannot be written: folder \"no\\nsuch\" does not exist");
    CHECK(error_of([] { load_scene("two\nlines.json"); }) ==
          "\"two\\nlines.json\": must be a scene file (JSON or pbrt-v4), got no such file");
}

TEST_CASE("Staging names are short, unique per process, never someone else's, and removed on every path",
          "[bad_input][staging]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        auto staged_names = [] {
            std::vector<std::string> names;
            for (const auto& e : fs::directory_iterator(".")) {
                if (e.path().filename().string().ends_with(".staging")) names.push_back(e.path().filename());
            }
            return names;
        };
        const std::string longest(251, 'n');  // 255 bytes with ".png": the longest name a folder takes
        {
            StagedFile a(longest + ".png"), b(longest + ".png");
            const auto names = staged_names();
            REQUIRE(names.size() == 2);
            CHECK(names[0] != names[1]);
            for (const std::string& n : names) {
                CHECK(n.size() <= 40);
                CHECK(n.find(std::to_string(::getpid())) != std::string::npos);
            }
        }
        CHECK(staged_names().empty());  // removed, never committed
        {
            StagedFile c("kept.png");
            std::fputs("whole", c.file());
            c.commit();
        }
        CHECK(contents("kept.png") == "whole");
        CHECK(staged_names().empty());
        // A signal handler's removal: every live staging file goes, the committed ones stay.
        {
            StagedFile d("d.png");
            StagedFile e("e.png");
            std::fputs("e", e.file());
            e.commit();
            CHECK(staged_names().size() == 1);
            remove_staged_files_now();
            CHECK(staged_names().empty());
            CHECK(contents("e.png") == "e");
        }
        // The names the old code used for someone else's file (m.obj.tmp) and for its own stay untouched.
        std::ofstream("m.obj.tmp") << "theirs";
        check_writable("m.obj");
        CHECK(contents("m.obj.tmp") == "theirs");
        // A folder that takes no new file is found by the probe: /proc takes none, even for root.
        CHECK_THAT(error_of([] { check_writable("/proc/x.png"); }),
                   Catch::StartsWith("/proc/x.png: cannot be written: folder /proc does not take a new file"));
        CHECK_NOTHROW(check_writable(longest + ".png"));
        CHECK_THAT(error_of([&] { check_writable(longest + ".partial.png"); }),
                   Catch::EndsWith(": cannot be written: its name is 263 bytes, longer than the 255 its folder takes"));
    });
    fs::remove_all(folder);
}

TEST_CASE("Empty and overflowing flag values are refused, never replaced", "[bad_input][app]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        const std::vector<std::string> base{"--width", "4", "--height", "3", "--quiet", "--out", "w.png"};
        auto status = [&](std::vector<std::string> extra) {
            std::vector<std::string> args = base;
            args.insert(args.end(), extra.begin(), extra.end());
            return run_fake_chapter(args, [](const RunContext& c) -> std::optional<ChapterRun> {
                return fake_run(c, Color(1), false, 12);
            });
        };
        for (const auto& bad : std::vector<std::vector<std::string>>{
                 {"--scene", ""}, {"--out", ""}, {"--reference", ""}, {"--seed", "18446744073709551616"},
                 {"--seed", " -1"}, {"--seed", "-1"}, {"--seed", "0x10"}, {"--seed", "010"}, {"--seed", "1 "},
                 {"--spp", "1e1"}, {"--threads", "+1"}, {"--out", ".png"}, {"--out", "folder/"}}) {
            INFO(bad[0] << " \"" << bad[1] << "\"");
            CHECK(status(bad) == kExitBadInput);
            CHECK(fs::is_empty("."));
        }
        CHECK(status({"--seed", "18446744073709551615"}) == kExitOk);
    });
    fs::remove_all(folder);
}

TEST_CASE("A reference that is the output's own PFM is refused, not overwritten", "[bad_input][app]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        write_pfm(Image(4, 3), "r.pfm");
        fs::create_symlink("r.pfm", "link.pfm");
        const auto before = contents("r.pfm");
        for (const std::vector<std::string>& args :
             {std::vector<std::string>{"--out", "r.png", "--reference", "r.pfm"},
              std::vector<std::string>{"--out", "./r.png", "--reference", "link.pfm"},
              std::vector<std::string>{"--out", "r.png", "--reference", "r.partial.pfm"}}) {
            std::vector<std::string> all{"--width", "4", "--height", "3", "--quiet"};
            all.insert(all.end(), args.begin(), args.end());
            CHECK(run_fake_chapter(all, [](const RunContext& c) -> std::optional<ChapterRun> {
                      return fake_run(c, Color(1), false, 12);
                  }) == kExitBadInput);
        }
        CHECK(contents("r.pfm") == before);
    });
    fs::remove_all(folder);
}

TEST_CASE("A run's outputs may not take one another's names, nor an input's", "[bad_input][app]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        std::ofstream("table.csv") << "a table\n";
        fs::create_symlink("table.csv", "link.png");
        write_pfm(Image(4, 3), "h.pfm");
        fs::create_symlink("h.pfm", "link.pfm");
        for (const std::vector<std::string>& args :
             {std::vector<std::string>{"--out", "h.png", "--heat", "h.partial.png"},
              std::vector<std::string>{"--out", "h.png", "--heat", "./sub/../h.partial.png"},
              std::vector<std::string>{"--out", "h.png", "--heat", "h.png"},
              std::vector<std::string>{"--out", "h.png", "--reference", "link.pfm"}}) {
            fs::create_directory("sub");
            std::vector<std::string> all{"--width", "4", "--height", "3", "--spp", "2", "--quiet"};
            all.insert(all.end(), args.begin(), args.end());
            CHECK(run_fake_chapter(all, [](const RunContext& c) -> std::optional<ChapterRun> {
                      return fake_run(c, Color(1), false, 12);
                  }) == kExitBadInput);
            CHECK_FALSE(fs::exists("h.png"));
        }
        // By name, by a path through other folders, and by a link to one file; an output and an input.
        CHECK(same_file("h.png", "sub/../h.png"));
        CHECK(same_file("link.png", "table.csv"));
        CHECK_FALSE(same_file("h.png", "h.partial.png"));
        CHECK(error_of([] {
                  check_files_apart({{"--out", "the image", "t.png"}, {"--csv", "the table", "link.png"}},
                                    {{"--scene", "the scene", "table.csv"}});
              }) ==
              "--csv: the table link.png is the scene table.csv: it would be replaced; give another name");
        CHECK(error_of([] {
                  check_files_apart({{"--out", "the image", "t.png"}, {"--csv", "the table", "./t.png"}}, {});
              }) ==
              "--csv: the table ./t.png is the image t.png: one would replace the other; give another name");
        CHECK(contents("table.csv") == "a table\n");
    });
    fs::remove_all(folder);
}

TEST_CASE("The image size validated is the one rendered: flags may override a scene's too large image",
          "[bad_input][app]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        std::ofstream("huge.json") << "{" << kCamera << R"(, "image": {"width": 65536, "height": 65536}})";
        auto render = [](const RunContext& c) -> std::optional<ChapterRun> {
            return fake_run(c, Color(1), false, 12);
        };
        CHECK(run_fake_chapter({"--scene", "huge.json", "--quiet", "--out", "h.png"}, render) == kExitBadInput);
        CHECK(run_fake_chapter({"--scene", "huge.json", "--width", "4", "--height", "3", "--quiet", "--out", "h.png"},
                               render) == kExitOk);
        CHECK(fs::exists("h.png"));
    });
    fs::remove_all(folder);
}

TEST_CASE("An interrupt once the render is done lets the complete image be written, and says so",
          "[bad_input][app]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        const int status = run_fake_chapter({"--width", "4", "--height", "3", "--quiet", "--out", "i.png"},
                                            [](const RunContext& c) -> std::optional<ChapterRun> {
                                                set_interrupt_requested(true);  // as if Ctrl-C came now
                                                return fake_run(c, Color(1), false, 12);
                                            });
        set_interrupt_requested(false);
        set_interrupt_phase(InterruptPhase::kRendering);
        CHECK(status == 130);
        CHECK(read_pfm("i.pfm").at(1, 1) == Color(1));  // the complete image, not a partial one
        CHECK_FALSE(fs::exists("i.partial.pfm"));
    });
    fs::remove_all(folder);
}

namespace {

// The one line loading `scene` (in tests/data/bad_scenes) gives, and the line expected.tsv gives for it.
std::pair<std::string, std::string> bad_scene_message(const std::string& scene) {
    std::string message;
    in_folder(kBadScenes, [&] { message = error_of([&] { load_scene(scene); }); });
    return {message, expected_messages().at(scene)};
}

// A scene of one sphere whose albedo is the texture `file`.
std::string textured_scene(const std::string& file) {
    return "{" + std::string(kCamera) +
           R"(, "materials": {"w": {"type": "diffuse", "albedo": {"texture": ")" + file +
           R"("}}}, "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "w"}]})";
}

}  // namespace

TEST_CASE("A C1 control character in a name is escaped, as a control byte is", "[bad_input][message]") {
    // U+009B is the one-character CSI: "\u009b[2J" would clear a terminal that takes C1 controls.
    CHECK(shown("\xc2\x9b[2Jred.png") == "\"\\u009b[2Jred.png\"");
    CHECK(printable("a\xc2\x85z") == "a\\u0085z");
    // Other characters stay as they are.
    CHECK(shown("caf\xc3\xa9.png") == "\"caf\xc3\xa9.png\"");
    CHECK(printable("\xc2\xa0\xe2\x82\xac") == "\xc2\xa0\xe2\x82\xac");
    const auto [message, expected] = bad_scene_message("texture_c1_name.json");
    CHECK(message == expected);
    CHECK(message.find("\xc2\x9b") == std::string::npos);
}

TEST_CASE("A byte that is not UTF-8 in a folder's name is escaped as a hexadecimal escape", "[bad_input][message]") {
    CHECK(shown("caf\xe9/scene.json") == "\"caf\\xe9/scene.json\"");
    CHECK(error_of([] { load_scene("caf\xe9/scene.json"); }) ==
          "\"caf\\xe9/scene.json\": must be a scene file (JSON or pbrt-v4), got no such file");
    // An overlong form, a surrogate, a sequence cut short: each byte escaped.
    CHECK(printable("\xc0\xaf") == "\\xc0\\xaf");
    CHECK(printable("\xed\xa0\x80") == "\\xed\\xa0\\x80");
    CHECK(printable("\xe2\x82") == "\\xe2\\x82");
    // A cut never splits a character into bytes that are not UTF-8.
    CHECK(printable("ab\xe2\x82\xac", 3) == "ab...");
}

TEST_CASE("A texture that is a GIF, BMP, TGA, PPM or HDR image is refused: textures are PNG or JPEG",
          "[bad_input][texture]") {
    const auto [message, expected] = bad_scene_message("texture_gif.json");
    CHECK(message == expected);
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        using namespace std::string_literals;
        // Each one pixel, as stb_image would decode it.
        const std::map<std::string, std::string> files = {
            {"one.bmp",
             "BM\x3a\0\0\0\0\0\0\0\x36\0\0\0\x28\0\0\0\1\0\0\0\1\0\0\0\1\0\x18\0\0\0\0\0\4\0\0\0"s +
                 std::string(16, '\0') + "\x40\x80\xc0\0"s},
            {"one.tga", "\0\0\2\0\0\0\0\0\0\0\0\0\1\0\1\0\x18\0\x40\x80\xc0"s},
            {"one.ppm", "P6\n1 1\n255\n\xc0\x80\x40"s},
            {"one.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n\x80\x80\x80\x81"s},
        };
        const std::map<std::string, std::string> kinds = {
            {"one.bmp", "a BMP image"},
            {"one.tga", "neither (the file starts with \"\\x00\\x00\\x02\\x00\\x00\\x00\\x00\\x00\")"},
            {"one.ppm", "a PPM image"},
            {"one.hdr", "a Radiance HDR image"}};
        for (const auto& entry : files) {
            const std::string& file = entry.first;
            INFO(file);
            std::ofstream(file, std::ios::binary) << entry.second;
            CHECK(error_of([&] { parse_scene(textured_scene(file), "t.json"); }) ==
                  "t.json: materials.w.albedo.texture: " + file + ": must be a PNG or JPEG image, got " +
                      kinds.at(file));
        }
    });
    fs::remove_all(folder);
}

TEST_CASE("A PNG whose palette index is past its palette is refused, naming the pixel",
          "[bad_input][texture]") {
    const auto [message, expected] = bad_scene_message("texture_palette_index.json");
    CHECK(message == expected);
    // Two colours, indices 0 and 1, colour 0 transparent (tRNS): within the palette, so it loads.
    const char kTwoColours[] =
        "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x02\x00\x00\x00\x01"
        "\x08\x03\x00\x00\x00\xc3\xfc\x8f\xb8\x00\x00\x00\x06\x50\x4c\x54\x45\xff\x00\x00\x00\x00\xff\x6c"
        "\xa1\xfd\x8e\x00\x00\x00\x01\x74\x52\x4e\x53\x00\x40\xe6\xd8\x66\x00\x00\x00\x0b\x49\x44\x41\x54"
        "\x78\xda\x63\x60\x60\x04\x00\x00\x04\x00\x02\x2c\xde\x48\xad\x00\x00\x00\x00\x49\x45\x4e\x44\xae"
        "\x42\x60\x82";
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        std::ofstream("two.png", std::ios::binary) << std::string(kTwoColours, sizeof kTwoColours - 1);
        const Scene scene = parse_scene(textured_scene("two.png"), "t.json");
        REQUIRE(scene.materials.size() == 1);
    });
    fs::remove_all(folder);
}

TEST_CASE("A PNG with a chunk whose CRC does not match its data is refused, naming the chunk",
          "[bad_input][texture]") {
    const auto [message, expected] = bad_scene_message("texture_bad_crc.json");
    CHECK(message == expected);
    const auto [truncated, truncated_expected] = bad_scene_message("texture_truncated.json");
    CHECK(truncated == truncated_expected);
}

TEST_CASE("A PFM whose scale is not 1 or -1 is refused, not read as if it were", "[bad_input][image]") {
    const fs::path folder = temporary_folder();
    in_folder(folder, [&] {
        const float rgb[3] = {0.5f, 0.25f, 1};
        for (const char* scale : {"-2.0", "0.5"}) {
            INFO(scale);
            {
                std::ofstream out("scaled.pfm", std::ios::binary);
                out << "PF\n1 1\n" << scale << "\n";
                out.write(reinterpret_cast<const char*>(rgb), sizeof rgb);
            }
            CHECK(error_of([] { read_pfm("scaled.pfm"); }) ==
                  "scaled.pfm: PFM header's scale must be 1 or -1 (its sign gives the byte order; no other "
                  "magnitude is read), got " +
                      std::string(scale[0] == '-' ? "-2" : "0.5"));
        }
    });
    fs::remove_all(folder);
}

TEST_CASE("An OBJ index before any v, vt or vn line says there is none, not a range [1, 0]",
          "[bad_input][obj]") {
    auto obj_error = [](const std::string& text) { return error_of([&] { parse_obj(text, 1e9); }); };
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    CHECK(obj_error(tri + "f 1//1 2//1 3//1\nvn 0 0 1\n") ==
          "line 4, column 6: normal index \"1\" refers to a vn line, but none comes before it");
    CHECK(obj_error(tri + "f 1/1 2/1 3/1\n") ==
          "line 4, column 5: texture coordinate index \"1\" refers to a vt line, but none comes before it");
    CHECK(obj_error("f -1 -2 -3\n") ==
          "line 1, column 3: vertex index \"-1\" refers to a v line, but none comes "
          "before it");
    CHECK(obj_error("f 1 2 3\n") ==
          "line 1, column 3: vertex index \"1\" refers to a v line, but none comes "
          "before it");
}

TEST_CASE("A PLY index or count of 4294967295 is printed whole, not as 4.29497e+09", "[bad_input][ply]") {
    auto ply_error = [](const std::string& bytes) { return error_of([&] { parse_ply(bytes, 1e9); }); };
    auto header = [](const char* list) {
        return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nelement face 1\nproperty list " +
               std::string(list) + " vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
    };
    CHECK(ply_error(header("uchar uint") + "3 0 1 4294967295\n") ==
          "line 13: element face 0: vertex_indices: a vertex index must be in [0, 2], got 4294967295");
    CHECK(ply_error(header("uint uint") + "4294967295 0 1 2\n") ==
          "line 13: element face 0: vertex_indices: a face must have 3 to 65536 vertices, got 4294967295");
}
