// Tests of common: images and their files, random numbers, the render loop, scene loading, effects.
#include <stb_image.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <span>
#include <stdexcept>
#include <thread>
#include <vector>

#ifdef RT_TEST_OPENEXR
#include <ImfArray.h>
#include <ImfChannelList.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#endif

#include "rt/core/did_you_mean.hpp"
#include "rt/io/effects.hpp"
#include "rt/core/error_metrics.hpp"
#include "rt/core/errors.hpp"
#include "rt/core/random.hpp"
#include "rt/flags/enum_flag.hpp"
#include "rt/flags/study_flags.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/environment_image.hpp"
#include "rt/io/exr_file.hpp"
#include "rt/io/image_io.hpp"
#include "rt/io/input_file.hpp"
#include "rt/io/output_files.hpp"
#include "rt/io/picture_compare.hpp"
#include "rt/io/ply_parser.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/live/live_knobs.hpp"
#include "rt/render/interrupt.hpp"
#include "rt/render/parallel_for.hpp"
#include "rt/render/render_loop.hpp"

using namespace rt;
namespace fs = std::filesystem;

namespace {

fs::path temporary_folder() {
    const fs::path folder = fs::temp_directory_path() / ("rt_common_test_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    return folder;
}

std::string load_error(const std::string& text) {
    try {
        parse_scene(text, "bad.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

const char* kMinimalCamera = R"("camera": {"from": [0,0,0], "at": [0,0,-1], "up": [0,1,0], "vfov": 45})";

}  // namespace

#ifdef RT_TEST_OPENEXR
TEST_CASE("An OpenEXR environment image reads as its PFM does, wherever its data window starts", "[image]") {
    // Values a half float holds exactly, so the .exr stores them without rounding.
    Image image(6, 3);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) image.at(x, y) = Color(Real(x) * 0.25f, Real(y) * 2, 1024.f / Real(1 << x));
    const fs::path pfm = temporary_folder() / "sky_exact.pfm";
    write_pfm(image, pfm);
    for (const Imath::V2i& corner : {Imath::V2i(0, 0), Imath::V2i(-3, 7)}) {
        INFO("data window from (" << corner.x << ", " << corner.y << ")");
        const Imath::Box2i window(corner, corner + Imath::V2i(image.width() - 1, image.height() - 1));
        Imf::Array2D<Imf::Rgba> pixels(image.height(), image.width());
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const Color c = image.at(x, y);
                pixels[y][x] = Imf::Rgba(c.r, c.g, c.b, 1);
            }
        const fs::path exr = temporary_folder() / "sky_exact.exr";
        {
            Imf::RgbaOutputFile file(exr.c_str(), Imf::Header(window, window), Imf::WRITE_RGB);
            file.setFrameBuffer(&pixels[0][0] - corner.x - corner.y * image.width(), 1, std::size_t(image.width()));
            file.writePixels(image.height());
        }
        const Image from_exr = read_environment_image(exr), from_pfm = read_environment_image(pfm);
        REQUIRE(from_exr.width() == image.width());
        REQUIRE(from_exr.height() == image.height());
        for (std::size_t i = 0; i < image.pixel_count(); ++i) {
            CHECK(from_exr.pixels()[i] == image.pixels()[i]);
            CHECK(from_exr.pixels()[i] == from_pfm.pixels()[i]);
        }
    }
}
#endif

#ifdef RT_TEST_OPENEXR
TEST_CASE("An EXR written and read back: floats bit for bit, half floats within half precision", "[image]") {
    Image image(9, 4);
    Pcg32 rng(3, 4);
    for (Color& c : image.pixels())
        c = Color(rng.next_real() * 100, rng.next_real() * 1e-3f, -rng.next_real() * 1e-6f);
    image.at(0, 0) = Color(0.25f, 1024, 65504);  // half floats hold these exactly
    image.at(1, 0) = Color(65505, -1e6f, 3e38f);  // beyond a half float's range: held as +-65504
    const fs::path folder = temporary_folder();
    write_exr(image, folder / "round_trip_float.exr", ExrChannels::kFloat);
    write_exr(image, folder / "round_trip_half.exr", ExrChannels::kHalf);
    const Image floats = read_exr(folder / "round_trip_float.exr");
    const Image halves = read_exr(folder / "round_trip_half.exr");
    REQUIRE(floats.width() == 9);
    REQUIRE(floats.height() == 4);
    REQUIRE(halves.width() == 9);
    REQUIRE(halves.height() == 4);
    for (std::size_t i = 0; i < image.pixel_count(); ++i) {
        CHECK(std::memcmp(&floats.pixels()[i], &image.pixels()[i], sizeof(Color)) == 0);
        for (int c = 0; c < 3; ++c) {
            // Half floats: 11 significant bits (a relative error up to 2^-11); below 2^-14, a step of 2^-24.
            const float v = std::clamp(float(image.pixels()[i][c]), -kHalfMax, kHalfMax);
            const float back = float(halves.pixels()[i][c]);
            INFO("pixel " << i << ", channel " << c << ": " << v << " read back as " << back);
            CHECK(std::abs(back - v) <= std::max(std::abs(v) * std::ldexp(1.f, -11), std::ldexp(1.f, -25)));
        }
    }
    CHECK(halves.at(0, 0) == Color(0.25f, 1024, 65504));
    CHECK(halves.at(1, 0) == Color(65504, -65504, 65504));
    CHECK(beyond_half_range(image) == 3);
}

TEST_CASE("An EXR's NaN, infinite or negative pixel is refused as a PFM's is", "[image]") {
    const fs::path folder = temporary_folder();
    Image image(3, 2);
    image.at(1, 0) = Color(0.5f, std::numeric_limits<float>::quiet_NaN(), 1);
    write_exr(image, folder / "nan.exr", ExrChannels::kHalf);
    write_pfm(image, folder / "nan.pfm");
    const std::string nan_exr = (folder / "nan.exr").string(), nan_pfm = (folder / "nan.pfm").string();
    CHECK_THROWS_WITH(read_exr(nan_exr), nan_exr + ": pixel (1, 0) must be finite, got 0.5 nan 1");
    CHECK_THROWS_WITH(read_pfm(nan_pfm), nan_pfm + ": pixel (1, 0) must be finite, got 0.5 nan 1");
    image.at(1, 0) = Color(0.5f);
    image.at(2, 1) = Color(std::numeric_limits<float>::infinity(), 0, 0);
    write_exr(image, folder / "infinite.exr", ExrChannels::kFloat);
    const std::string infinite = (folder / "infinite.exr").string();
    CHECK_THROWS_WITH(read_exr(infinite), infinite + ": pixel (2, 1) must be finite, got inf 0 0");
    image.at(2, 1) = Color(-0.25f, 0, 0);
    write_exr(image, folder / "negative.exr", ExrChannels::kHalf);
    const std::string negative = (folder / "negative.exr").string();
    CHECK(read_exr(negative).at(2, 1) == Color(-0.25f, 0, 0));
    CHECK_THROWS_WITH(read_exr(negative, PfmPixels::kRadiance),
                      negative + ": pixel (2, 1) must be finite radiance, >= 0, got -0.25 0 0");
}

TEST_CASE("--out x.exr writes x.exr, x.png and x.SUFFIX.exr together, and names them with their partial twins",
          "[image]") {
    const fs::path folder = temporary_folder() / "exr_outputs";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const ImageOutput out = image_output(folder / "x.exr", false);
    CHECK(out.format == RadianceFormat::kExrHalf);
    CHECK(image_output(folder / "x.exr", true).format == RadianceFormat::kExrFloat);
    std::vector<std::string> names;
    for (const RunFile& f : image_outputs(out, false, {".noisy"})) names.push_back(f.path.filename().string());
    CHECK(names == std::vector<std::string>{"x.exr", "x.png", "x.noisy.exr", "x.partial.exr", "x.partial.png",
                                            "x.partial.film", "x.partial.noisy.exr"});
    Image image(4, 2), noisy(4, 2);
    image.at(1, 1) = Color(1e5f, 0.5f, 2);
    noisy.at(3, 0) = Color(0.25f);
    const std::string written = write_outputs(image, out, nullptr, {ExtraImage{".noisy", noisy}});
    const std::string x = (folder / "x").string();
    CHECK(written == x + ".exr (1 channel value(s) beyond a half float's range held as +-65504; --exr-float keeps "
                         "them), " + x + ".png and " + x + ".noisy.exr");
    CHECK(read_exr(folder / "x.exr").at(1, 1) == Color(65504, 0.5f, 2));
    CHECK(read_exr(folder / "x.noisy.exr").at(3, 0) == Color(0.25f));
    std::set<std::string> files;
    for (const auto& entry : fs::directory_iterator(folder)) files.insert(entry.path().filename().string());
    CHECK(files == std::set<std::string>{"x.exr", "x.png", "x.noisy.exr"});
}

TEST_CASE("An EXR without R, G and B, truncated, or not OpenEXR is refused, naming the file", "[image]") {
    const fs::path folder = temporary_folder();
    const std::string grey = (folder / "grey.exr").string();
    {
        Imf::Header header(2, 2);
        header.channels().insert("Y", Imf::Channel(Imf::HALF));
        Imf::OutputFile file(grey.c_str(), header);  // no pixels written: the file is incomplete too
    }
    CHECK_THROWS_WITH(read_exr(grey), grey + ": must hold the channels R, G and B, got Y");
    Image image(64, 64);
    for (Color& c : image.pixels()) c = Color(0.5f);
    write_exr(image, folder / "whole.exr", ExrChannels::kFloat);
    const std::string bytes = read_whole_file(folder / "whole.exr");
    const std::string truncated = (folder / "truncated.exr").string();
    std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() - 40);
    CHECK_THROWS_WITH(read_exr(truncated), Catch::StartsWith(truncated + ": "));
    const std::string text = (folder / "text.exr").string();
    std::ofstream(text) << "not an EXR file";
    CHECK_THROWS_WITH(read_exr(text), Catch::StartsWith(text + ": must be an OpenEXR file it can read ("));
    CHECK_THROWS_WITH(read_exr(folder / "absent.exr"),
                      (folder / "absent.exr").string() + ": must be an OpenEXR file, got no such file");
}
#endif

TEST_CASE("A PFM written and read back is the same image, bit for bit", "[image]") {
    Image image(7, 5);
    Pcg32 rng(1, 2);
    for (Color& c : image.pixels())
        c = Color(rng.next_real() * 100, rng.next_real() * 1e-3f, -rng.next_real());
    const fs::path file = temporary_folder() / "round_trip.pfm";
    write_pfm(image, file);
    const Image back = read_pfm(file);
    REQUIRE(back.width() == 7);
    REQUIRE(back.height() == 5);
    for (std::size_t i = 0; i < image.pixel_count(); ++i) CHECK(back.pixels()[i] == image.pixels()[i]);
    const ErrorMetrics e = compare(back, image);
    CHECK(e.rmse == 0);
    CHECK(e.mean_error == 0);
}

TEST_CASE("A PNG is written whole under its name, with no temporary file left", "[image]") {
    const fs::path folder = temporary_folder() / "png_alone";
    fs::create_directories(folder);
    Image image(4, 3);
    image.at(1, 1) = Color(0.5f);
    write_png(image, folder / "picture.png");
    CHECK(fs::file_size(folder / "picture.png") > 0);
    // Nothing else: no staging file (.rt-PID-N.staging) is left beside it.
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    CHECK(names == std::vector<std::string>{"picture.png"});
}

TEST_CASE("A PNG written and read back holds the tone-mapped, sRGB-encoded bytes", "[image]") {
    Image image(5, 3);
    Pcg32 rng(5, 6);
    for (Color& c : image.pixels())
        c = Color(rng.next_real() * 1.5f, rng.next_real(), rng.next_real() * 0.01f);
    const fs::path file = temporary_folder() / "round_trip.png";
    write_png(image, file);
    int width = 0, height = 0, channels = 0;
    unsigned char* bytes = stbi_load(file.c_str(), &width, &height, &channels, 3);
    REQUIRE(bytes != nullptr);
    CHECK(width == 5);
    CHECK(height == 3);
    for (std::size_t i = 0; i < image.pixel_count(); ++i) {
        const Color& c = image.pixels()[i];
        CHECK(bytes[3 * i] == to_display_byte(c.r));
        CHECK(bytes[3 * i + 1] == to_display_byte(c.g));
        CHECK(bytes[3 * i + 2] == to_display_byte(c.b));
    }
    stbi_image_free(bytes);
}

TEST_CASE("Writing into a missing folder is bad input and creates nothing", "[image]") {
    const fs::path file = temporary_folder() / "no_such_folder" / "x.png";
    CHECK_THROWS_AS(write_png(Image(2, 2), file), InputError);
    CHECK_FALSE(fs::exists(file.parent_path()));
}

TEST_CASE("Reading a broken PFM names the file and the problem", "[image]") {
    const fs::path file = temporary_folder() / "broken.pfm";
    std::ofstream(file) << "PF\n4 4\n-1.0\n"
                        << "short";
    CHECK_THROWS_WITH(read_pfm(file), Catch::Contains("broken.pfm") && Catch::Contains("truncated"));
    CHECK_THROWS_WITH(read_pfm(temporary_folder() / "absent.pfm"),
                      Catch::EndsWith("absent.pfm: must be a PFM file, got no such file"));
}

TEST_CASE("sRGB encoding follows the standard's two pieces and clamps", "[image]") {
    CHECK(srgb_encode(0) == 0);
    CHECK(srgb_encode(1) == Approx(1).epsilon(1e-6));
    CHECK(srgb_encode(0.002f) == Approx(12.92 * 0.002));
    CHECK(srgb_encode(0.5f) == Approx(1.055 * std::pow(0.5, 1 / 2.4) - 0.055));
    CHECK(to_display_byte(2.0f) == 255);
    CHECK(to_display_byte(-1.0f) == 0);
    CHECK(to_display_byte(std::nanf("")) == 0);
}

TEST_CASE("Image sizes that are not positive or would not fit in memory are refused before allocation",
          "[image]") {
    CHECK_THROWS_WITH(check_image_size(0, 10), Catch::Contains("must be positive"));
    CHECK_THROWS_WITH(check_image_size(65536, 65536), Catch::Contains("needs") && Catch::Contains("GB"));
    CHECK_NOTHROW(check_image_size(640, 480));
}

TEST_CASE("PCG32 is deterministic per (pixel, sample, seed) and streams differ", "[random]") {
    Pcg32 a = Pcg32::for_sample(12, 3, 7), b = Pcg32::for_sample(12, 3, 7);
    for (int i = 0; i < 100; ++i) REQUIRE(a.next_uint() == b.next_uint());
    std::set<std::uint32_t> firsts;
    for (std::uint64_t pixel = 0; pixel < 1000; ++pixel)
        firsts.insert(Pcg32::for_sample(pixel, 0, 7).next_uint());
    for (std::uint64_t sample = 0; sample < 1000; ++sample)
        firsts.insert(Pcg32::for_sample(5, sample, 7).next_uint());
    CHECK(firsts.size() >= 1995);  // 2000 streams; a 32-bit collision among them is rare, not forbidden
    CHECK(Pcg32::for_sample(1, 1, 1).next_uint() != Pcg32::for_sample(1, 1, 2).next_uint());
}

TEST_CASE("PCG32 reals are uniform between 0 and 1: chi-square over 100 cells", "[random][statistical]") {
    constexpr int kCells = 100;
    constexpr int kSamples = 1'000'000;
    std::vector<int> counts(kCells, 0);
    Pcg32 rng(42, 54);
    for (int i = 0; i < kSamples; ++i) {
        const Real u = rng.next_real();
        REQUIRE(u >= 0);
        REQUIRE(u < 1);
        ++counts[std::size_t(u * kCells)];
    }
    const double expected = double(kSamples) / kCells;
    double chi_square = 0;
    for (int c : counts) chi_square += (c - expected) * (c - expected) / expected;
    // The 99th percentile of the chi-square distribution with 99 degrees of freedom is 134.64.
    CHECK(chi_square < 134.64);
}

TEST_CASE("The largest uniform real is the largest float below 1", "[random]") {
    CHECK(Real(0xFFFFFF) * Real(0x1.0p-24) == kOneMinusEpsilon);
    CHECK(kOneMinusEpsilon < 1);
    CHECK(std::nextafter(kOneMinusEpsilon, Real(2)) == 1);
}

TEST_CASE("The parallel engine runs every item once, on any number of threads", "[render][parallel]") {
    for (int threads : {1, 2, 3, 8}) {
        std::vector<std::atomic<int>> runs(1000);
        std::atomic<int> bad_thread{0};
        const bool whole = parallel_for(runs.size(), {.threads = threads}, [&](std::size_t item, int thread) {
            if (thread < 0 || thread >= threads) ++bad_thread;
            ++runs[item];
        });
        CHECK(whole);
        CHECK(bad_thread == 0);
        CHECK(std::all_of(runs.begin(), runs.end(), [](const std::atomic<int>& n) { return n == 1; }));
    }
}

TEST_CASE("The parallel engine on one thread runs every item in order on the calling thread", "[render][parallel]") {
    std::vector<std::size_t> order;
    bool elsewhere = false;
    const std::thread::id caller = std::this_thread::get_id();
    parallel_for(5, {.threads = 1}, [&](std::size_t item, int) {
        order.push_back(item);
        elsewhere = elsewhere || std::this_thread::get_id() != caller;
    });
    CHECK(order == std::vector<std::size_t>{0, 1, 2, 3, 4});
    CHECK_FALSE(elsewhere);
}

namespace {
std::atomic<int> items_before_stop{0};
bool stop_after_three() { return items_before_stop.fetch_add(1) >= 3; }
}  // namespace

TEST_CASE("The parallel engine starts no item once stopped, and says it stopped", "[render][parallel]") {
    items_before_stop = 0;
    int ran = 0;
    const bool whole = parallel_for(10, {.threads = 1, .stop = stop_after_three}, [&](std::size_t, int) { ++ran; });
    CHECK_FALSE(whole);
    CHECK(ran == 3);
}

TEST_CASE("The parallel engine rethrows the first exception once every thread has finished its item",
          "[render][parallel]") {
    std::atomic<int> started{0}, finished{0};
    auto run = [&] {
        parallel_for(64, {.threads = 4}, [&](std::size_t item, int) {
            ++started;
            if (item == 0) throw std::runtime_error("first");
            std::this_thread::sleep_for(std::chrono::milliseconds(item == 1 ? 100 : 20));
            if (item == 1) throw std::runtime_error("second");
            ++finished;
        });
    };
    CHECK_THROWS_WITH(run(), "first");
    // Every item that started had ended (finished or thrown) before the rethrow, and the failure stopped the
    // hand-out early.
    CHECK(started - finished <= 2);
    CHECK(started < 64);
    const int finished_at_rethrow = finished;
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    CHECK(finished == finished_at_rethrow);
}

TEST_CASE("The render loop gives the same image, bit for bit, for 1 and 2 threads", "[render]") {
    auto sample = [](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        rays.add(RayKind::kCamera);
        return Color(rng.next_real(), Real(s.x) * 0.01f + rng.next_real(), Real(s.index));
    };
    RenderSettings settings{37, 29, 7, 5, 1, ProgressStyle::kNone};
    const RenderResult one = render(settings, sample);
    settings.threads = 2;
    const RenderResult two = render(settings, sample);
    REQUIRE(one.image.pixel_count() == two.image.pixel_count());
    for (std::size_t i = 0; i < one.image.pixel_count(); ++i)
        REQUIRE(one.image.pixels()[i] == two.image.pixels()[i]);
    CHECK(one.rays[RayKind::kCamera] == 37u * 29u * 7u);
    CHECK(two.rays[RayKind::kCamera] == 37u * 29u * 7u);
    CHECK(one.samples == 37u * 29u * 7u);
    CHECK_FALSE(one.interrupted);
    // Sample indices 0..6 average to 3: each pixel is the mean of its samples.
    CHECK(one.image.at(36, 28).b == Approx(3));
}

TEST_CASE("An interrupt stops the render within one sample, and the first pass's unsampled pixels are named",
          "[render]") {
    // One thread; the interrupt comes with the 300th sample: no sample starts after it, the tile it cut short
    // is dropped (its pixels keep no half pass), and the pixels left without a sample are counted.
    int taken = 0, after_interrupt = 0;
    auto sample = [&](const PixelSample&, Pcg32&, RayCounts&) {
        if (interrupt_requested()) ++after_interrupt;
        if (++taken == 300) set_interrupt_requested(true);
        return Color(1);
    };
    const RenderSettings settings{40, 20, 4, 1, 1, ProgressStyle::kNone};
    const RenderResult r = render(settings, sample);
    set_interrupt_requested(false);
    CHECK(after_interrupt == 0);
    CHECK(taken == 300);
    CHECK(r.interrupted);
    CHECK(r.samples_per_pixel == 0);
    // Tiles of 16 × 16: the first (256 pixels) is whole; the second was cut short at its 44th sample.
    CHECK(r.samples == 256);
    CHECK(r.unsampled_pixels == 40u * 20u - 256u);
    CHECK(r.unsampled_region.x0 == 0);
    CHECK(r.unsampled_region.y0 == 0);
    CHECK(r.unsampled_region.x1 == 40);
    CHECK(r.unsampled_region.y1 == 20);
    CHECK(r.image.at(0, 0) == Color(1));
    CHECK(r.image.at(16, 0) == Color(0));  // the tile cut short keeps nothing of its pass
    int sampled = 0;
    for (const Color& c : r.image.pixels()) sampled += c == Color(1) ? 1 : 0;
    CHECK(sampled == 256);
}

TEST_CASE("An interrupt after the first pass leaves every pixel the mean of whole passes", "[render]") {
    int taken = 0;
    const int first_pass = 40 * 20;
    auto sample = [&](const PixelSample& s, Pcg32&, RayCounts&) {
        if (++taken == first_pass + 100) set_interrupt_requested(true);
        return Color(Real(s.index));
    };
    const RenderSettings settings{40, 20, 64, 1, 1, ProgressStyle::kNone};
    const RenderResult r = render(settings, sample);
    set_interrupt_requested(false);
    CHECK(r.interrupted);
    CHECK(r.unsampled_pixels == 0);
    CHECK(r.samples_per_pixel == 1);
    // Sample 0 for every pixel, then a pass of samples 1..8 kept by no tile: the image is sample 0's value.
    for (const Color& c : r.image.pixels()) REQUIRE(c == Color(0));
    CHECK(r.samples == std::uint64_t(first_pass));
}

TEST_CASE("The observer sees every pass's sums, and the image is the same with it", "[render][live]") {
    auto sample = [](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        rays.add(RayKind::kCamera);
        return Color(rng.next_real(), Real(s.index), 1);
    };
    // 17 samples: the first pass takes 1, then passes of ⌈17/8⌉ = 3: 1 + 16/3 rounded up = 7 passes.
    RenderSettings settings{20, 18, 17, 9, 2, ProgressStyle::kNone};
    const RenderResult without = render(settings, sample);
    std::vector<std::uint32_t> counts;
    std::vector<std::uint64_t> samples, camera_rays;
    Image last;
    AfterEachPass watch([&](const PassReport& pass) {
        counts.push_back(pass.fewest_samples);
        samples.push_back(pass.samples);
        CHECK(pass.samples_held == pass.samples);
        camera_rays.push_back(pass.rays[RayKind::kCamera]);
        last = pass.image;
    });
    settings.observer = &watch;
    const RenderResult with = render(settings, sample);
    CHECK(counts == std::vector<std::uint32_t>{1, 4, 7, 10, 13, 16, 17});
    const std::uint64_t pixels = 20 * 18;
    CHECK(samples == std::vector<std::uint64_t>{pixels, 4 * pixels, 7 * pixels, 10 * pixels, 13 * pixels,
                                                16 * pixels, 17 * pixels});
    CHECK(camera_rays == samples);
    for (std::size_t i = 0; i < with.image.pixel_count(); ++i) {
        REQUIRE(with.image.pixels()[i] == without.image.pixels()[i]);
        REQUIRE(last.pixels()[i] == with.image.pixels()[i]);
    }
}

// Records what the loop measures of each pixel, as the app's heat maps do.
class CostRecorder final : public RenderObserver {
public:
    CostRecorder(int width, bool measures) : width_(width), measures_(measures), cost_(std::size_t(width * width)) {}
    bool measures_cost() const override { return measures_; }
    void add_cost(int x, int y, const PixelCost& cost) override {
        PixelCost& sum = cost_[std::size_t(y * width_ + x)];
        sum.rays += cost.rays;
        sum.bounces += cost.bounces;
        sum.samples += cost.samples;
        ++calls_;
    }
    const std::vector<PixelCost>& cost() const { return cost_; }
    int calls() const { return calls_; }

private:
    int width_;
    bool measures_;
    std::vector<PixelCost> cost_;
    std::atomic<int> calls_{0};
};

TEST_CASE("The observer is told each pixel's rays, bounces and samples, only when it measures them",
          "[render][heat]") {
    // Pixel (x, y) takes 1 + x camera rays and y indirect ones (its bounces) per sample.
    auto sample = [](const PixelSample& s, Pcg32&, RayCounts& rays) {
        rays.add(RayKind::kCamera, std::uint64_t(1 + s.x));
        rays.add(RayKind::kIndirect, std::uint64_t(s.y));
        return Color(1);
    };
    const int size = 20, spp = 9;
    RenderSettings settings{size, size, spp, 1, 2, ProgressStyle::kNone};
    CostRecorder measured(size, true);
    settings.observer = &measured;
    render(settings, sample);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const PixelCost& c = measured.cost()[std::size_t(y * size + x)];
            REQUIRE(c.samples == std::uint64_t(spp));
            REQUIRE(c.rays == std::uint64_t(spp * (1 + x + y)));
            REQUIRE(c.bounces == std::uint64_t(spp * y));
        }
    }
    CostRecorder unmeasured(size, false);
    settings.observer = &unmeasured;
    render(settings, sample);
    CHECK(unmeasured.calls() == 0);
}

TEST_CASE("A restart of the live view stops the render as an interrupt does, and is no signal", "[render][live]") {
    int taken = 0;
    auto sample = [&](const PixelSample&, Pcg32&, RayCounts&) {
        if (++taken == 400) set_render_restart(true);
        return Color(1);
    };
    const RenderSettings settings{40, 20, 8, 1, 1, ProgressStyle::kNone};
    const RenderResult r = render(settings, sample);
    CHECK(render_restart_requested());
    CHECK(interrupt_requested());
    CHECK_FALSE(signal_received());
    set_render_restart(false);
    CHECK_FALSE(interrupt_requested());
    CHECK(r.interrupted);
    CHECK(taken == 400);
    CHECK(r.samples == 256);  // the first tile's first pass; the second tile's, cut short, is dropped
}

namespace {

enum class Fruit { kApple, kPear, kPlum };

constexpr auto names_of(Fruit) {
    return enum_names<Fruit>("--fruit", {{Fruit::kApple, "apple"}, {Fruit::kPear, "pear"}, {Fruit::kPlum, "plum"}});
}

}  // namespace

TEST_CASE("An enum's one table of names gives to_string, parsing and its error, and the flag with its choices",
          "[flags]") {
    for (Fruit f : {Fruit::kApple, Fruit::kPear, Fruit::kPlum}) CHECK(from_string<Fruit>(to_string(f)) == f);
    CHECK(to_string(Fruit::kPlum) == "plum");
    CHECK(joined_names<Fruit>() == "apple|pear|plum");
    CHECK_THROWS_AS(from_string<Fruit>("Apple"), InputError);
    CHECK_THROWS_WITH(from_string<Fruit>("fig"), "--fruit: expected apple, pear or plum, got \"fig\"");
    CHECK_THROWS_WITH(from_string<Fruit>("a\nb"), "--fruit: expected apple, pear or plum, got \"a\\nb\"");

    CLI::App app("test", "test");
    app.option_defaults()->always_capture_default();
    Fruit fruit = Fruit::kPear;
    add_enum_option(app, fruit, "Which fruit");
    std::vector<std::string> none;
    app.parse(none);
    CHECK(fruit == Fruit::kPear);
    const LiveKnobs knobs(app, {"--help"}, {});
    REQUIRE(knobs.knobs().size() == 1);
    CHECK(knobs.knobs()[0].name == "--fruit");
    CHECK(knobs.knobs()[0].choices == std::vector<std::string>{"apple", "pear", "plum"});
    CHECK(knobs.knobs()[0].value == "pear");  // the default, by its name
    std::vector<std::string> plum{"plum", "--fruit"};  // CLI11 reads the vector last first
    app.parse(plum);
    CHECK(fruit == Fruit::kPlum);
    std::vector<std::string> fig{"fig", "--fruit"};
    CHECK_THROWS_WITH(app.parse(fig), "--fruit: fig not in {apple,pear,plum}");
}

TEST_CASE("A study's shared options take their name and help from one table, and are refused without the study",
          "[flags]") {
    CLI::App app("test", "test");
    bool study = false;
    std::string csv;
    int reference_spp = 8;
    CLI::Option* study_flag = app.add_flag("--aa-study", study, "A study");
    const CLI::Option* csv_option = add_study_option(app, kCsvOption, csv, {{study_flag}});
    const CLI::Option* spp_option = add_reference_spp_option(app, reference_spp, 2, {{study_flag}}, "Its own words");
    CHECK(csv_option->get_name() == "--csv");
    CHECK(csv_option->get_description() == "With --aa-study: also write the table as CSV");
    CHECK(spp_option->get_name() == "--reference-spp");
    CHECK(spp_option->get_description() == "Its own words");
    std::vector<std::string> alone{"t.csv", "--csv"};  // CLI11 reads the vector last first
    CHECK_THROWS_WITH(app.parse(alone), Catch::Contains("only with --aa-study"));
    std::vector<std::string> too_few{"1", "--reference-spp", "--aa-study"};
    CHECK_THROWS(app.parse(too_few));
    std::vector<std::string> both{"4", "--reference-spp", "t.csv", "--csv", "--aa-study"};
    app.parse(both);
    CHECK(csv == "t.csv");
    CHECK(reference_spp == 4);
}

TEST_CASE("The live view's knobs are a chapter's flags that take a value, set as the command line sets them",
          "[live]") {
    CLI::App app("test", "test");
    app.option_defaults()->always_capture_default();  // as run_chapter() does: --help shows the defaults
    std::string sampling = "mis";
    std::optional<int> depth;
    bool study = false;
    int study_runs = 10;
    std::string variant = "connect";
    double aperture = 0.1;
    app.add_option("--scene", "core");
    app.add_option("--sampling", sampling, "How directions are drawn")
        ->check(CLI::IsMember({"uniform", "mis"}));
    app.add_option("--max-depth", depth, "Bounces at most")->check(CLI::Range(1, 1000));
    app.add_flag("--study", study, "A demo mode");
    app.add_option("--study-runs", study_runs, "With --study: runs per row");
    app.add_option("--variant", variant, "connect or aperture")->check(CLI::IsMember({"connect", "aperture"}));
    CLI::Option* aperture_option = app.add_option("--aperture", aperture, "With --variant aperture: the radius");
    // As chapter 08 does: a check after the values are stored.
    app.parse_complete_callback([aperture_option, &variant] {
        if (aperture_option->count() > 0 && variant != "aperture")
            throw CLI::ValidationError("--aperture", "is used only with --variant aperture");
    });
    std::vector<std::string> args{"--variant", "aperture", "--aperture", "0.5"};
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app.parse(reversed);
    LiveKnobs knobs(app, {"--help", "--scene"}, args);
    std::vector<std::string> names;
    for (const Knob& k : knobs.knobs()) names.push_back(k.name);
    // --study takes no value, --study-runs is its mode's, --scene is core: none is a knob.
    CHECK(names == std::vector<std::string>{"--sampling", "--max-depth", "--variant", "--aperture"});
    CHECK(knobs.knobs()[0].choices == std::vector<std::string>{"uniform", "mis"});
    CHECK(knobs.knobs()[0].value == "mis");
    CHECK(knobs.knobs()[1].value == "");  // no default
    CHECK(knobs.knobs()[3].value == "0.5");

    knobs.set("--sampling", "uniform");
    CHECK(sampling == "uniform");
    CHECK(knobs.knobs()[0].value == "uniform");
    knobs.set("--max-depth", "3");
    CHECK(depth == 3);
    CHECK(aperture == 0.5);  // the command line's values stay
    CHECK_THROWS_WITH(knobs.set("--sampling", "sideways"),
                      "usage: --sampling: sideways not in {uniform,mis} (see --help)");
    CHECK_THROWS_WITH(knobs.set("--max-depth", "0"),
                      "usage: --max-depth: Value 0 not in range 1 to 1000 (see --help)");
    CHECK(sampling == "uniform");
    CHECK(depth == 3);
    // Refused by a check that runs after the values are stored: they are set back all the same.
    CHECK_THROWS_WITH(knobs.set("--variant", "connect"),
                      "usage: --aperture: is used only with --variant aperture (see --help)");
    CHECK(variant == "aperture");
    CHECK(knobs.knobs()[2].value == "aperture");
    CHECK_THROWS_AS(knobs.set("--study-runs", "3"), InputError);
    // undo() takes back the last change that was accepted.
    knobs.set("--sampling", "mis");
    CHECK(sampling == "mis");
    knobs.undo();
    CHECK(sampling == "uniform");
    CHECK(knobs.knobs()[0].value == "uniform");
}

TEST_CASE("Edit distance and did-you-mean find near misses only", "[scene]") {
    CHECK(edit_distance("radius", "radius") == 0);
    CHECK(edit_distance("raduis", "radius") == 2);
    CHECK(edit_distance("", "abc") == 3);
    constexpr std::string_view names[] = {"sphere", "quad", "triangle"};
    CHECK(closest_match("sphre", names) == std::optional<std::string>("sphere"));
    CHECK_FALSE(closest_match("cylinder", names).has_value());
}

TEST_CASE("The course's scenes all load", "[scene]") {
    int loaded = 0;
    for (const auto& entry : fs::directory_iterator(assets_dir() / "scenes")) {
        if (entry.path().extension() != ".json") continue;
        INFO(entry.path());
        CHECK_NOTHROW(load_scene(entry.path()));
        ++loaded;
    }
    CHECK(loaded >= 2);
}

TEST_CASE("The Cornell box loads as assets/scenes/README.md describes it", "[scene]") {
    const Scene scene = load_scene(scene_path("cornell.json"));
    CHECK(scene.shapes.size() == 8);
    CHECK(scene.materials.size() == 5);
    CHECK(scene.image.width == 600);
    CHECK(scene.camera.vfov == 40);
    const auto& box = std::get<BoxShape>(scene.shapes[6].geometry);
    CHECK(box.transform.rotate_degrees.y == 15);
    // The turned box's corner (165, 0, 0) lands at (265 + 165 cos 15°, 0, 295 − 165 sin 15°).
    const Vec3 corner = box.transform.apply_to_point(Vec3(165, 0, 0));
    CHECK(corner.x == Approx(265 + 165 * std::cos(radians(15))));
    CHECK(corner.z == Approx(295 - 165 * std::sin(radians(15))));
    CHECK(scene.has_area_lights());
}

TEST_CASE("A loaded scene lists every file it read: the scene, its textures, meshes and environment image",
          "[scene]") {
    // What a run's outputs are checked against (app.cpp): each path as the loader opened it.
    const auto inputs_of = [](const char* name) {
        const fs::path assets = assets_dir().lexically_normal();
        std::vector<std::string> inputs;
        for (const SceneInput& input : load_scene(scene_path(name)).inputs) {
            const fs::path path = input.path.lexically_normal().lexically_relative(assets);
            inputs.push_back(input.what + " " + path.generic_string());
        }
        return inputs;
    };
    CHECK(inputs_of("ch04_textured.json") ==
          std::vector<std::string>{"the scene scenes/ch04_textured.json",
                                   "the texture of materials.crate textures/ch04_wood.png",
                                   "the texture of materials.wood textures/ch04_wood.png"});
    CHECK(inputs_of("ch04_smooth_mesh.json") ==
          std::vector<std::string>{"the scene scenes/ch04_smooth_mesh.json",
                                   "the mesh of shapes[2] meshes/ch04_torus.obj",
                                   "the mesh of shapes[3] meshes/ch04_torus.ply"});
    CHECK(inputs_of("ch06_sky.json") == std::vector<std::string>{"the scene scenes/ch06_sky.json",
                                                                 "the environment image environments/sky.hdr"});
    CHECK(inputs_of("cornell.json") == std::vector<std::string>{"the scene scenes/cornell.json"});
}

TEST_CASE("Scene errors name the file, the place and what was expected", "[scene]") {
    const std::string camera = kMinimalCamera;
    CHECK(load_error(R"({"camera": {"from": [0,0,0], "at": [0,0,-1], "vfov": 0}})") ==
          "bad.json: camera.vfov: must be in (0, 180), got 0");
    CHECK(load_error("{" + camera + R"(, "materials": {"white": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "white"},
                   {"type": "sphere", "center": [0,0,0], "radius": -1, "material": "white"}]})") ==
          "bad.json: shapes[1].radius: must be > 0, got -1");
    CHECK(load_error("{" + camera + R"(, "materials": {"white": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "centre": [0,0,0], "radius": 1, "material": "white"}]})") ==
          "bad.json: shapes[0].centre: unknown key for a sphere (did you mean \"center\"?)");
    CHECK(load_error("{" + camera + R"(, "materials": {"white": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "center": [0,0], "radius": 1, "material": "white"}]})") ==
          "bad.json: shapes[0].center: must be an array of 3 numbers, got an array of 2");
    CHECK(load_error("{" + camera + R"(, "materials": {"white": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "whte"}]})") ==
          "bad.json: shapes[0].material: unknown material \"whte\" (did you mean \"white\"?)");
    CHECK(load_error("{" + camera + R"(, "materials": {"white": {"type": "diffuse"}},
        "shapes": [{"type": "quad", "origin": [0,0,0], "u": [1,0,0], "v": [2,0,0], "material": "white"}]})") ==
          "bad.json: shapes[0]: quad must have an area (u and v not parallel, not zero), got u = [1, 0, 0], "
          "v = [2, 0, 0]");
    CHECK(load_error(R"({"camera": {"from": [0,0,0], "at": [0,1,0], "up": [0,2,0]}})") ==
          "bad.json: camera.up: must not be parallel to the view direction at - from = [0, 1, 0], got [0, 2, "
          "0]");
    CHECK(load_error(R"({"camera": {"at": [0,1,0]}})") ==
          "bad.json: camera: missing required field \"from\"");
    CHECK(load_error(R"({"camera": {"from": [0,0,0], "at": [0,0,1e40]}})") ==
          "bad.json: camera.at[2]: must be a finite number of magnitude at most 1e+09, got 1e+40");
    CHECK_THAT(load_error(R"({"camera": {"from": [0,0,0], )"), Catch::StartsWith("bad.json: not valid JSON"));
    CHECK(load_error("{" + camera + R"(, "materials": {"lamp": {"type": "diffuse", "emission": [1,-1,1]}},
        "shapes": [{"type": "sphere", "center": [0,0,0], "radius": 1, "material": "lamp"}]})") ==
          "bad.json: materials.lamp.emission[1]: must be in [0, 1e+09], got -1");
    CHECK(load_error("{" + camera + R"(, "materials": {"white": {"type": "diffuse"}}})") ==
          "bad.json: materials.white: defined but used by no shape (use it or remove it)");
}

TEST_CASE("Mesh errors name the scene, the place and the OBJ file", "[scene]") {
    const fs::path folder = temporary_folder();
    auto scene_with_mesh = [&](const std::string& obj_name) {
        return "{" + std::string(kMinimalCamera) + R"(, "materials": {"white": {"type": "diffuse"}},
            "shapes": [{"type": "mesh", "file": ")" +
               obj_name + R"(", "material": "white"}]})";
    };
    auto error_for = [&](const std::string& text) {
        try {
            parse_scene(text, folder / "mesh.json");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK_THAT(
        error_for(scene_with_mesh("absent.obj")),
        Catch::Contains("shapes[0].file: must name an OBJ or PLY file") && Catch::Contains("absent.obj"));
    std::ofstream(folder / "empty.obj") << "# nothing\n";
    CHECK_THAT(error_for(scene_with_mesh("empty.obj")),
               Catch::Contains("empty.obj: must have at least one face, got none"));
    std::ofstream(folder / "out_of_range.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n";
    CHECK_THAT(error_for(scene_with_mesh("out_of_range.obj")),
               Catch::Contains("shapes[0].file") &&
                   Catch::EndsWith("out_of_range.obj: line 4, column 7: vertex index must be a whole number in "
                                   "[1, 3] (or negative, counting back from the last), got \"9\""));
    std::ofstream(folder / "good.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
    const Scene scene = parse_scene(scene_with_mesh("good.obj"), folder / "mesh.json");
    const auto& mesh = std::get<MeshShape>(scene.shapes[0].geometry);
    CHECK(mesh.positions.size() == 4);  // shared vertices stay shared
    CHECK(mesh.triangles.size() == 2);
}

TEST_CASE("needed(scene) follows the content, narrowed by the scene's effects list", "[effects]") {
    const std::string camera = kMinimalCamera;
    const Scene empty = parse_scene("{" + camera + "}", "e.json");
    CHECK(needed(empty) == EffectSet{Effect::kCameraRays});

    const Scene lit = parse_scene("{" + camera + R"(, "materials": {"white": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "center": [0,0,-3], "radius": 1, "material": "white"}],
        "lights": [{"type": "point", "position": [0,5,0], "intensity": [10,10,10]}]})",
                                  "l.json");
    CHECK(needed(lit) ==
          EffectSet{Effect::kCameraRays, Effect::kShadows, Effect::kDirect, Effect::kIndirect});

    const Scene unlit_glass = parse_scene("{" + camera + R"(, "materials": {"glass": {"type": "dielectric"}},
        "shapes": [{"type": "sphere", "center": [0,0,-3], "radius": 1, "material": "glass"}]})",
                                          "g.json");
    CHECK(needed(unlit_glass) == EffectSet{Effect::kCameraRays, Effect::kReflection, Effect::kRefraction});

    const Scene narrowed = parse_scene("{" + camera + R"(, "materials": {"white": {"type": "diffuse"}},
        "shapes": [{"type": "sphere", "center": [0,0,-3], "radius": 1, "material": "white"}],
        "lights": [{"type": "environment", "radiance": [1,1,1]}], "effects": ["shadows", "direct"]})",
                                       "n.json");
    CHECK(needed(narrowed) == EffectSet{Effect::kCameraRays, Effect::kShadows, Effect::kDirect});

    const Scene cornell = load_scene(scene_path("cornell.json"));
    CHECK(needed(cornell) ==
          EffectSet::all().without(EffectSet{Effect::kGlossy, Effect::kMedia, Effect::kShadingNormals}));
}

TEST_CASE("needed(scene) lights whatever a light can reach: media that scatter, mirrors and glass too",
          "[effects]") {
    const EffectSet lighting{Effect::kShadows, Effect::kDirect, Effect::kIndirect};
    const auto lit = [&](const std::string& rest) {
        const Scene scene = parse_scene("{" + std::string(kMinimalCamera) + rest + "}", "s.json");
        return (needed(scene) & lighting) == lighting;
    };
    const std::string point = R"(, "lights": [{"type": "point", "position": [0,5,0], "intensity": [9,9,9]}])";
    const std::string sky = R"(, "lights": [{"type": "environment", "radiance": [1,1,1]}])";
    const std::string fog = R"(, "medium": {"sigma_a": [0.01,0.01,0.01], "sigma_s": [0.2,0.2,0.2]})";
    const auto sphere_of = [](const std::string& material) {
        return R"(, "materials": {"m": )" + material +
               R"(}, "shapes": [{"type": "sphere", "center": [0,0,-3], "radius": 1, "material": "m"}])";
    };
    // Fog lit by a point light, with nothing else in the scene; a sphere of milk under a sky.
    CHECK(lit(fog + point));
    CHECK(lit(sky + sphere_of(R"({"type": "dielectric", "medium": {"sigma_s": [1,1,1]}})")));
    // A mirror and smooth glass under a lamp (chapters 03 and 04 shade them as lit Lambert stand-ins).
    CHECK(lit(point + sphere_of(R"({"type": "mirror"})")));
    CHECK(lit(point + sphere_of(R"({"type": "dielectric"})")));
    // Nothing a light can reach: fog that only absorbs, a black surface, a black mirror; and no light.
    CHECK_FALSE(lit(point + R"(, "medium": {"sigma_a": [0.1,0.1,0.1]})"));
    CHECK_FALSE(lit(point + sphere_of(R"({"type": "diffuse", "albedo": [0,0,0]})")));
    CHECK_FALSE(lit(point + sphere_of(R"({"type": "mirror", "reflectance": [0,0,0]})")));
    CHECK_FALSE(lit(fog + sphere_of(R"({"type": "diffuse"})")));
}

TEST_CASE("The variance of a pixel's mean from exact sums: samples 1, 2, 3, 4 give 5/12", "[variance]") {
    PixelSum sum, squares;
    for (int i = 1; i <= 4; ++i) {
        sum.add(Color(Real(i)));
        squares.add(Color(Real(i * i)));
    }
    // s² = (30 − 100/4) / 3 = 5/3, and Var[mean] = s² / 4.
    CHECK(variance_of_mean(sum, squares).r == Approx(5.0 / 12));
    PixelSum one, one_square;
    one.add(Color(3));
    one_square.add(Color(9));
    CHECK(variance_of_mean(one, one_square) == Color(0));
}

TEST_CASE("Layered sums estimate the variance of a pixel's mean without bias", "[variance][statistical]") {
    // Each sample uniform in [0, 1) (variance 1/12), 8 a pixel, summed with its square as a layer beside the
    // image: Var[mean] = 1/96. The estimate, averaged over 64x64 pixels, and the scatter of the pixels' means
    // both come out at 1/96.
    RenderSettings s;
    s.width = 64, s.height = 64, s.samples_per_pixel = 8, s.seed = 3, s.threads = 2,
    s.progress = ProgressStyle::kNone;
    std::array<PixelSums, 1> squares;
    const RenderResult r = render_layers(s, squares, [](const PixelSample&, Pcg32& rng, RayCounts&) {
        const Color u(rng.next_real());
        return std::array<Color, 2>{u, u * u};
    });
    const Image variance = variance_image(r.sums, squares[0]);
    double estimated = 0;
    for (const Color& v : variance.pixels()) estimated += double(v.r) / double(variance.pixel_count());
    CHECK(estimated == Approx(1.0 / 96).epsilon(0.03));
    double sum = 0, sum_of_squares = 0;
    for (const Color& v : r.image.pixels()) {
        sum += v.r;
        sum_of_squares += double(v.r) * v.r;
    }
    const double n = double(r.image.pixel_count());
    CHECK((sum_of_squares - sum * sum / n) / (n - 1) == Approx(1.0 / 96).epsilon(0.05));
}

TEST_CASE("The error over a region is the error of the crop", "[metrics]") {
    Image image(6, 5), reference(6, 5), crop_image(3, 2), crop_reference(3, 2);
    Pcg32 rng(2, 9);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 6; ++x) {
            image.at(x, y) = Color(rng.next_real(), rng.next_real(), rng.next_real());
            reference.at(x, y) = Color(rng.next_real(), rng.next_real(), rng.next_real());
            if (x >= 2 && x < 5 && y >= 1 && y < 3) {
                crop_image.at(x - 2, y - 1) = image.at(x, y);
                crop_reference.at(x - 2, y - 1) = reference.at(x, y);
            }
        }
    }
    const ErrorMetrics region = compare(image, reference, PixelRect{2, 1, 5, 3});
    const ErrorMetrics cropped = compare(crop_image, crop_reference);
    CHECK(region.rmse == cropped.rmse);
    CHECK(region.relative_mse == cropped.relative_mse);
    CHECK(region.mean_error == cropped.mean_error);
    CHECK_THROWS(compare(image, reference, PixelRect{2, 1, 7, 3}));
}

TEST_CASE("Pictures: a PNG reads back as written, and a comparison counts, bounds and maps the pixels that differ",
          "[image]") {
    Image image(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) image.at(x, y) = Color(Real(x) / 15, Real(y) / 7, 0.5f);
    const auto path = std::filesystem::temp_directory_path() / ("rt_picture_" + std::to_string(getpid()) + ".png");
    write_png(image, path);
    const Picture read = read_png(path);
    std::filesystem::remove(path);
    const Picture made = to_picture(image);
    CHECK(read.width == 16);
    CHECK(read.height == 8);
    CHECK(read.rgb == made.rgb);
    const PictureDifference same = compare_pictures(read, made, 0);
    CHECK(same.differing == 0);
    CHECK(same.largest == 0);
    // Two pixels changed, in the top left and bottom right regions, by 3 and 40 levels.
    Picture changed = made;
    changed.rgb[(1 * 16 + 1) * 3] = std::uint8_t(changed.rgb[(1 * 16 + 1) * 3] + 3);
    changed.rgb[(7 * 16 + 14) * 3 + 2] = std::uint8_t(changed.rgb[(7 * 16 + 14) * 3 + 2] - 40);
    const PictureDifference d = compare_pictures(changed, made, 0);
    CHECK(d.differing == 2);
    CHECK(d.largest == 40);
    CHECK((d.min_x == 1 && d.min_y == 1 && d.max_x == 14 && d.max_y == 7));
    CHECK(compare_pictures(changed, made, 3).differing == 1);  // the 3-level change is within tolerance
    const std::string text = describe(d, "");
    CHECK(text.find("2 of 128 pixels differ by more than 0 of 255") != std::string::npos);
    // The 8 × 8 map: region (0, 0) and region (7, 7), each of 2 pixels, half of which differ.
    CHECK(text.find("|#       |") != std::string::npos);
    CHECK(text.find("|       #|") != std::string::npos);
    CHECK_THROWS_AS(compare_pictures(to_picture(Image(4, 4)), made, 0), InputError);
}

TEST_CASE("PLY reads the same mesh from ASCII, binary little-endian and big-endian data", "[ply]") {
    const std::string header_start = "ply\nformat ";
    const std::string header_rest =
        " 1.0\ncomment a quad and a triangle\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nproperty uchar red\nproperty float nx\nproperty float ny\nproperty float nz\n"
        "property double s\nproperty double t\nelement face 2\nproperty uchar flags\n"
        "property list uchar uint vertex_indices\nelement edge 1\nproperty int vertex1\nproperty int "
        "vertex2\n"
        "end_header\n";
    const rt::PlyMesh ascii = rt::parse_ply(header_start + "ascii" + header_rest +
                                                "0 0 0 255 0 0 1 0 0\n1 0 0 7 0 0 2 1 0\n1 1 0 7 0 1 1 1 1\n"
                                                "0 1 0 7 1 0 0 0.5 1\n0 4 0 1 2 3\n1 3 0 2 3\n0 2\n",
                                            1e9);
    REQUIRE(ascii.positions.size() == 4);
    CHECK(ascii.positions[2] == rt::Vec3(1, 1, 0));
    CHECK(ascii.normals[1] == rt::Vec3(0, 0, 2));  // as written: the loader normalises
    CHECK(ascii.texture_coordinates[3] == rt::Vec2(0.5f, 1));
    REQUIRE(ascii.face_count() == 2);
    CHECK(std::vector(ascii.face(0).begin(), ascii.face(0).end()) == std::vector<std::uint32_t>{0, 1, 2, 3});
    CHECK(std::vector(ascii.face(1).begin(), ascii.face(1).end()) == std::vector<std::uint32_t>{0, 2, 3});
    for (const bool little : {true, false}) {
        std::string data;
        auto put = [&](auto value) {
            char bytes[sizeof value];
            std::memcpy(bytes, &value, sizeof value);  // this machine is little-endian (x86-64)
            if (!little) std::reverse(bytes, bytes + sizeof value);
            data.append(bytes, sizeof value);
        };
        for (std::size_t v = 0; v < 4; ++v) {
            for (int a = 0; a < 3; ++a) put(float(ascii.positions[v][a]));
            put(std::uint8_t(7));
            for (int a = 0; a < 3; ++a) put(float(ascii.normals[v][a]));
            for (int a = 0; a < 2; ++a) put(double(ascii.texture_coordinates[v][a]));
        }
        for (std::size_t f = 0; f < ascii.face_count(); ++f) {
            const std::span<const std::uint32_t> face = ascii.face(f);
            put(std::uint8_t(0));
            put(std::uint8_t(face.size()));
            for (const std::uint32_t i : face) put(i);
        }
        put(std::int32_t(0)), put(std::int32_t(2));
        const rt::PlyMesh binary = rt::parse_ply(
            header_start + (little ? "binary_little_endian" : "binary_big_endian") + header_rest + data, 1e9);
        INFO((little ? "little-endian" : "big-endian"));
        CHECK(binary.positions == ascii.positions);
        CHECK(binary.normals == ascii.normals);
        CHECK(binary.texture_coordinates == ascii.texture_coordinates);
        CHECK(binary.corners == ascii.corners);
        CHECK(binary.face_starts == ascii.face_starts);
    }
}

TEST_CASE("The scene loader reads a mesh as PLY by its extension, quads as fans, normals normalised",
          "[ply]") {
    const fs::path folder = fs::temp_directory_path() / ("rt_ply_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "quad.PLY")
        << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
           "property float nx\nproperty float ny\nproperty float nz\nelement face 1\n"
           "property list uchar int vertex_indices\nend_header\n0 0 0 0 0 2\n1 0 0 0 0 2\n1 1 0 0 0 2\n0 1 0 "
           "0 0 2\n"
           "4 0 1 2 3\n";
    std::ofstream(folder / "scene.json")
        << R"({"camera": {"from": [0, 0, 5], "at": [0, 0, 0]}, "materials": {"m": {"type": "diffuse"}},
              "shapes": [{"type": "mesh", "file": "quad.PLY", "material": "m"}]})";
    const rt::Scene scene = rt::load_scene(folder / "scene.json");
    const auto& mesh = std::get<rt::MeshShape>(scene.shapes[0].geometry);
    CHECK(mesh.triangles == std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {0, 2, 3}});
    CHECK(mesh.normal_corners == mesh.triangles);
    CHECK(mesh.normals[3] == rt::Vec3(0, 0, 1));
    CHECK(mesh.texture_coordinates.empty());
    CHECK(rt::needed(scene).contains(rt::Effect::kShadingNormals));
    fs::remove_all(folder);
}

TEST_CASE(
    "A mesh mirrored by its transform keeps its outside: every face still turns counter-clockwise from it",
    "[scene]") {
    const fs::path folder = temporary_folder();
    // A tetrahedron whose faces turn counter-clockwise seen from outside, its centroid at the origin.
    std::ofstream(folder / "tetrahedron.obj") << "v 1 1 1\nv -1 -1 1\nv -1 1 -1\nv 1 -1 -1\n"
                                                 "vn 1 1 1\nvn -1 -1 1\nvn -1 1 -1\nvn 1 -1 -1\n"
                                                 "f 1//1 2//2 4//4\nf 1//1 3//3 2//2\nf 1//1 4//4 3//3\n"
                                                 "f 2//2 3//3 4//4\n";
    for (const char* scale : {"1", "[-1, 1, 1]", "[1, -2, 1]", "[-1, -1, -1]", "[-1, -1, 1]"}) {
        INFO("scale " << scale);
        const Scene scene =
            parse_scene("{" + std::string(kMinimalCamera) +
                            R"(, "materials": {"white": {"type": "diffuse"}}, "shapes": [{"type":
            "mesh", "file": "tetrahedron.obj", "transform": {"scale": )" +
                            scale + R"(}, "material": "white"}]})",
                        folder / "mesh.json");
        const auto& mesh = std::get<MeshShape>(scene.shapes[0].geometry);
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
            const auto& [a, b, c] = mesh.triangles[i];
            const Vec3 face_normal =
                glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
            const Vec3 centroid = (mesh.positions[a] + mesh.positions[b] + mesh.positions[c]) / Real(3);
            CHECK(glm::dot(face_normal, centroid) > 0);  // the mesh's centre stays at the origin
            // Each corner's normal (the transform's inverse transpose) agrees with the face's side.
            for (int k = 0; k < 3; ++k)
                CHECK(glm::dot(face_normal, mesh.normals[mesh.normal_corners[i][k]]) > 0);
        }
    }
}
