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

#include "rt/app.hpp"
#include "rt/errors.hpp"
#include "rt/image_io.hpp"
#include "rt/pixel_sums.hpp"
#include "rt/random.hpp"
#include "rt/scene_loader.hpp"

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
        if (entry.path().extension() == ".json") files.insert(entry.path().filename().string());
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
            CHECK(message.rfind(file + ": ", 0) == 0);  // it starts with the file's name
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

TEST_CASE("A scene image too large for memory is refused before allocation, with the size it needs",
          "[bad_input]") {
    const std::string text = "{" + std::string(kCamera) + R"(, "image": {"width": 65536, "height": 65536}})";
    CHECK_THAT(error_of([&] { parse_scene(text, "huge.json"); }),
               Catch::StartsWith("huge.json: image: image size 65536x65536 needs " +
                                 gigabytes_of_buffers(65536, 65536) +
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
        CHECK(error_of([] { read_pfm("folder.pfm"); }) ==
              "folder.pfm: must be a PFM file, got something else (a folder?)");
        std::ofstream("p6.pfm") << "P6\n4 4\n255\n";
        CHECK(error_of([] { read_pfm("p6.pfm"); }) ==
              "p6.pfm: must be a colour PFM file starting with \"PF\", got \"P6\"");
        std::ofstream("zero.pfm") << "PF\n0 4\n-1.0\n";
        CHECK(error_of([] { read_pfm("zero.pfm"); }) ==
              "zero.pfm: PFM header must give a width and height in [1, 65536] and a non-zero scale, got 0 4 "
              "-1.000000");
        // A header that promises 51 GB is refused by the file's size, before anything is allocated.
        std::ofstream("huge.pfm") << "PF\n65536 65536\n-1.0\n" << std::string(100, 'x');
        CHECK(error_of([] { read_pfm("huge.pfm"); }) ==
              "huge.pfm: PFM data must be 51539607552 bytes for 65536x65536, got 100 (truncated)");
        {
            std::ofstream nan_file("nan.pfm", std::ios::binary);
            nan_file << "PF\n1 1\n-1.0\n";
            const float rgb[3] = {0.5f, std::numeric_limits<float>::quiet_NaN(), 1};
            nan_file.write(reinterpret_cast<const char*>(rgb), sizeof rgb);
        }
        CHECK(error_of([] { read_pfm("nan.pfm"); }) ==
              "nan.pfm: pixel (0, 0) must be finite, got 0.500000 nan 1.000000");
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
            CHECK(entry.path().filename().string().find(".partial-") == std::string::npos);
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
