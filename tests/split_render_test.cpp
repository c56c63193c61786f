// A render split by sample range: exact per-pixel sums, the render loop's pieces and resumes, the film file,
// the merge of pieces and the split among MPI ranks (the executables' side is tests/cli/split_render*.sh).
#include "rt/run/split_render.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <vector>

#include "rt/core/errors.hpp"
#include "rt/core/pixel_sums.hpp"
#include "rt/core/sample_range.hpp"
#include "rt/io/assets.hpp"
#include "rt/io/film.hpp"
#include "rt/io/scene_loader.hpp"
#include "rt/render/interrupt.hpp"
#include "rt/render/render_loop.hpp"
#include "rt/run/film_merge.hpp"
#include "rt/run/mpi_split.hpp"
#include "rt/run/render_identity.hpp"

using namespace rt;
namespace fs = std::filesystem;

namespace {

// Radiance-like samples over many magnitudes, as a path tracer's fireflies give.
std::vector<Color> wild_samples(int n) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0, 1);
    std::vector<Color> samples;
    for (int i = 0; i < n; ++i) {
        const float scale = std::pow(10.0f, unit(random) * 12 - 6);
        samples.emplace_back(unit(random) * scale, unit(random), -unit(random) * scale);
    }
    return samples;
}

bool same_bits(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::equal(a.pixels().begin(), a.pixels().end(), b.pixels().begin(),
                      [](const Color& x, const Color& y) { return std::memcmp(&x, &y, sizeof x) == 0; });
}

// A sample function that, like a stratified sampler, depends on the render's samples per pixel.
RenderSettings small_settings() {
    RenderSettings settings;
    settings.width = 21;
    settings.height = 19;
    settings.samples_per_pixel = 7;
    settings.seed = 3;
    settings.threads = 2;
    settings.progress = ProgressStyle::kNone;
    return settings;
}
auto stratified_sample(const RenderSettings& settings) {
    return [&settings](const PixelSample& s, Pcg32& rng, RayCounts& rays) {
        rays.add(RayKind::kCamera);
        const Real stratum = (Real(s.index) + rng.next_real()) / Real(settings.samples_per_pixel);
        return Color(stratum, rng.next_real() * Real(1e4), Real(s.x) * Real(0.1) + rng.next_real());
    };
}

}  // namespace

TEST_CASE("Exact sums are the same bits whatever the order and the split of the samples", "[split]") {
    const std::vector<Color> samples = wild_samples(1000);
    PixelSum in_order;
    for (const Color& c : samples) in_order.add(c);
    std::vector<Color> shuffled = samples;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(11));
    PixelSum any_order;
    for (const Color& c : shuffled) any_order.add(c);
    PixelSum pieces;
    for (std::size_t first = 0; first < samples.size(); first += 37) {  // pieces of 37, the last shorter
        PixelSum piece;
        for (std::size_t i = first; i < std::min(samples.size(), first + 37); ++i) piece.add(samples[i]);
        pieces.add(piece);
    }
    CHECK(in_order == any_order);
    CHECK(in_order == pieces);
    const Color a = in_order.mean(), b = any_order.mean();
    CHECK(std::memcmp(&a, &b, sizeof a) == 0);
    // A float sum in another order is not the same bits: this is what the exact sums are for.
    float forward = 0, backward = 0;
    for (const Color& c : samples) forward += c.r;
    for (auto it = samples.rbegin(); it != samples.rend(); ++it) backward += it->r;
    CHECK(forward != backward);
}

TEST_CASE("An exact mean is the float mean, rounded once", "[split]") {
    PixelSum one;
    one.add(Color(0.1f, 3.0f, 1e-6f));
    CHECK(one.mean() == Color(0.1f, 3.0f, 1e-6f));  // a single sample comes back as it went in
    PixelSum two;
    two.add(Color(0.25f));
    two.add(Color(0.75f));
    CHECK(two.mean() == Color(0.5f));
    const std::vector<Color> samples = wild_samples(100);
    PixelSum sum;
    double exact = 0;
    for (const Color& c : samples) {
        sum.add(c);
        exact += double(c.g);
    }
    CHECK(double(sum.mean().g) == Approx(exact / 100).epsilon(1e-7));
    CHECK(PixelSum{}.mean() == Color(0));
}

TEST_CASE("A pixel's sum stays 64 bytes, its high parts out of line and copied with it", "[split]") {
    CHECK(sizeof(PixelSum) == 64);
    PixelSum huge;
    huge.add(Color(0x1p60f, 1, 0x1p100f));
    const PixelSum copy = huge;
    huge.add(Color(0x1p60f, 1, 0x1p100f));
    CHECK(copy.high() == HighParts{1 << 10, 0, Int128(1) << 50});
    CHECK(huge.high() == HighParts{2 << 10, 0, Int128(2) << 50});
    PixelSum merged = copy;
    merged.add(copy);
    CHECK(merged == huge);
    CHECK(merged != copy);
    CHECK(PixelSum{}.high() == HighParts{});
}

TEST_CASE("NaN and infinite samples make the pixel NaN or infinite, as float addition would", "[split]") {
    const Real inf = std::numeric_limits<Real>::infinity(), nan = std::numeric_limits<Real>::quiet_NaN();
    PixelSum p;
    p.add(Color(inf, inf, nan));
    p.add(Color(-inf, inf, 1));
    const Color m = p.mean();
    CHECK(std::isnan(m.r));  // +inf and -inf
    CHECK(m.g == inf);
    CHECK(std::isnan(m.b));
}

TEST_CASE("Samples up to float's largest are summed, merged and filmed exactly, none clamped", "[split]") {
    // A point light of 1e9 at 1e-4 above a white floor (1e9 / (π 1e-8)), float's largest, and an ordinary
    // sample beside them.
    const Real largest = std::numeric_limits<float>::max();
    const Color first(Real(3.1830989e16), largest, Real(0.5)),
        second(Real(3.1830989e16), Real(3e38), Real(2e15));
    PixelSum one;
    one.add(first);
    CHECK(one.mean() == first);
    PixelSum two;
    two.add(first);
    two.add(second);
    const Color mean((double(first.r) + double(second.r)) / 2, (double(first.g) + double(second.g)) / 2,
                     (double(first.b) + double(second.b)) / 2);
    CHECK(two.mean() == mean);
    PixelSum negative;  // below −2^50 too
    negative.add(Color(-largest, Real(-1e20), Real(-0x1p50)));
    CHECK(negative.mean() == Color(-largest, Real(-1e20), Real(-0x1p50)));
    if constexpr (sizeof(Real) >
                  sizeof(float)) {  // a double build: beyond the sums, a sample counts as infinite
        PixelSum beyond;
        beyond.add(Color(Real(0x1p128), 0, 0));
        CHECK(beyond.mean().r == kInfinity);
    }
    // Two pieces of one sample each, filmed, read back and merged: the whole's sum, bit for bit.
    const FilmIdentity id{"ch00_test", "test.json", 42, "", 1, 1, 2, 3};
    auto piece = [&](SampleRange range, const Color& sample) {
        Film film{id, range, PixelSums(1, 1)};
        film.sums.at(0, 0).add(sample);
        return film;
    };
    const fs::path file = fs::temp_directory_path() / "rt_split_render_bright.film";
    write_film(piece({1, 2}, second), file);
    const Film merged = merge_films({{"a.film", piece({0, 1}, first)}, {"b.film", read_film(file)}});
    CHECK(merged.sums.at(0, 0) == two);
    CHECK(merged.sums.mean_image().at(0, 0) == mean);
    fs::remove(file);
}

TEST_CASE("split_range cuts a range into contiguous parts differing by at most one sample", "[split]") {
    CHECK(split_range({0, 5}, 3, 0) == SampleRange{0, 2});
    CHECK(split_range({0, 5}, 3, 1) == SampleRange{2, 4});
    CHECK(split_range({0, 5}, 3, 2) == SampleRange{4, 5});
    CHECK(split_range({4, 6}, 3, 2).size() == 0);  // more parts than samples: an empty part
    CHECK(split_range({4, 6}, 1, 0) == SampleRange{4, 6});
    CHECK(parse_sample_range("3:7", 7) == SampleRange{3, 7});
    CHECK_THROWS_AS(parse_sample_range("7:7", 7), InputError);
    CHECK_THROWS_AS(parse_sample_range("0:8", 7), InputError);
    CHECK_THROWS_AS(parse_sample_range("-1:2", 7), InputError);
    CHECK_THROWS_AS(parse_sample_range("1:2x", 7), InputError);
    // Read as strictly as every other flag's whole numbers: no sign, no leading 0.
    CHECK(parse_sample_range("0:4", 7) == SampleRange{0, 4});
    for (const char* text : {"-0:4", "+0:4", "00:4", "0:04", "0: 4", " 0:4"}) {
        INFO(text);
        CHECK_THROWS_AS(parse_sample_range(text, 7), InputError);
    }
}

TEST_CASE("The render loop's pieces, added, are the whole render bit for bit", "[split]") {
    const RenderSettings whole_settings = small_settings();
    const RenderResult whole = render(whole_settings, stratified_sample(whole_settings));
    PixelSums added(whole_settings.width, whole_settings.height);
    std::uint64_t rays = 0;
    for (const SampleRange r : {SampleRange{0, 1}, SampleRange{1, 4}, SampleRange{4, 5}, SampleRange{5, 7}}) {
        RenderSettings s = whole_settings;
        s.samples = r;
        const RenderResult piece = render(s, stratified_sample(s));
        CHECK(piece.samples_per_pixel == r.size());
        CHECK_FALSE(piece.interrupted);
        added.add(piece.sums);
        rays += piece.rays.total();
    }
    CHECK(added == whole.sums);
    CHECK(same_bits(added.mean_image(), whole.image));
    CHECK(rays == whole.rays.total());
}

TEST_CASE("An interrupted render, resumed, is the uninterrupted render bit for bit", "[split]") {
    RenderSettings settings = small_settings();
    settings.samples_per_pixel =
        40;  // passes of 1, then 5 samples: an interrupt leaves pixels at different counts
    const RenderResult whole = render(settings, stratified_sample(settings));
    int taken = 0;
    auto interrupting = [&, sample = stratified_sample(settings)](const PixelSample& s, Pcg32& rng,
                                                                  RayCounts& r) {
        if (++taken == 21 * 19 * 3)
            set_interrupt_requested(true);  // racy between threads, but only its timing
        return sample(s, rng, r);
    };
    settings.threads = 1;
    const RenderResult partial = render(settings, interrupting);
    set_interrupt_requested(false);
    REQUIRE(partial.interrupted);
    CHECK(partial.sums.min_count() < 40);
    settings.resume = &partial.sums;
    settings.threads = 2;
    const RenderResult resumed = render(settings, stratified_sample(settings));
    CHECK_FALSE(resumed.interrupted);
    CHECK(resumed.sums == whole.sums);
    CHECK(same_bits(resumed.image, whole.image));
    CHECK(partial.samples + resumed.samples == whole.samples);
}

TEST_CASE("A film written and read back is the same film, and a changed byte is refused as corrupt",
          "[split]") {
    RenderSettings settings = small_settings();
    settings.samples = SampleRange{2, 5};
    Film film{{"ch00_test", "test.json", 42, "--flag=1", settings.width, settings.height, 7, 3},
              {2, 5},
              render(settings, stratified_sample(settings)).sums};
    const fs::path file = fs::temp_directory_path() / "rt_split_render_test.film";
    write_film(film, file);
    const Film back = read_film(file);
    CHECK(back.identity == film.identity);
    CHECK(back.range == film.range);
    CHECK(back.sums == film.sums);
    CHECK(back.complete());
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(1000);
        f.put('\x7f');
    }
    CHECK_THROWS_WITH(read_film(file), Catch::Contains("corrupt: its checksum does not match"));
    fs::remove(file);
}

TEST_CASE("A film is input: negative sums, sums beyond its samples' reach and NaN flags are refused by name",
          "[split]") {
    RenderSettings settings = small_settings();
    const FilmIdentity id{"ch00_test", "test.json", 42, "", settings.width, settings.height, 7, 3};
    auto piece = [&](SampleRange r) {
        RenderSettings s = settings;
        s.samples = r;
        return Film{id, r, render(s, stratified_sample(s)).sums};
    };
    const fs::path file = fs::temp_directory_path() / "rt_split_render_values.film";
    // Each changed film is refused when read (rt_merge's pieces, --resume) and when merged from memory.
    using Reason = Catch::Matchers::Impl::MatcherBase<std::string>;
    auto refused = [&](const Film& film, const Reason& reason) {
        write_film(film, file);
        CHECK_THROWS_WITH(read_film(file), Catch::StartsWith(file.string() + ": pixel (3, 2) ") && reason);
        CHECK_THROWS_WITH(merge_films({{"a.film", film}, {"b.film", piece({3, 7})}}),
                          Catch::StartsWith("a.film: pixel (3, 2) ") && reason);
    };
    Film negative = piece({0, 3});
    negative.sums.at(3, 2).channels[1] = -negative.sums.at(3, 2).channels[1];
    refused(negative, Catch::Contains("has a sum of -") && Catch::Contains("in channel 1 for 3 samples") &&
                          Catch::Contains("radiance is never negative"));
    // Two such pieces would add to more than 2^127: the 128-bit sum would wrap.
    Film huge = piece({0, 3});
    huge.sums.at(3, 2).channels[0] = (Int128(1) << 126) + 1;
    refused(huge, Catch::Contains("in channel 0 for 3 samples, outside [-4.57764e-05, 3.3777e+15]"));
    // The parts of 2^50 and above: never negative, and below 2^128 a sample.
    Film high_negative = piece({0, 3});
    high_negative.sums.at(3, 2).add_high({0, 0, -1});
    refused(high_negative, Catch::Contains("has a sum of -1.1259e+15 in channel 2") &&
                               Catch::Contains("parts of 2^50 and above"));
    Film high_huge = piece({0, 3});
    high_huge.sums.at(3, 2).add_high({(Int128(3) << 78) + 1, 0, 0});
    refused(high_huge, Catch::Contains("in channel 0 for 3 samples, outside [0, 1.02085e+39]"));
    Film nan = piece({0, 3});
    nan.sums.at(3, 2).non_finite = PixelSum::kNan << 3;
    refused(nan, Catch::Contains("holds a NaN or infinite sample"));
    Film unknown = piece({0, 3});
    unknown.sums.at(3, 2).non_finite = 01000;
    refused(unknown, Catch::Contains("has unknown flags 512"));
    // The pieces as rendered are merged.
    CHECK(merge_films({{"a.film", piece({0, 3})}, {"b.film", piece({3, 7})}}).sums ==
          render(settings, stratified_sample(settings)).sums);
    fs::remove(file);
}

TEST_CASE("merge_films adds pieces given in any order, and names the piece that leaves a gap", "[split]") {
    const RenderSettings whole_settings = small_settings();
    const RenderResult whole = render(whole_settings, stratified_sample(whole_settings));
    const FilmIdentity id{"ch00_test",          "test.json",           42, "",
                          whole_settings.width, whole_settings.height, 7,  3};
    auto piece = [&](const char* name, SampleRange r) {
        RenderSettings s = whole_settings;
        s.samples = r;
        return FilmPiece{name, Film{id, r, render(s, stratified_sample(s)).sums}};
    };
    const Film merged = merge_films({piece("c", {6, 7}), piece("a", {0, 3}), piece("b", {3, 6})});
    CHECK(merged.range == SampleRange{0, 7});
    CHECK(merged.sums == whole.sums);
    CHECK_THROWS_WITH(merge_films({piece("a", {0, 3}), piece("c", {6, 7})}),
                      "c: takes samples 6:7, but samples 3:6 are in no piece (the piece before is a, 0:3)");
}

TEST_CASE("A whole render in one process leaves the sample range unset, so a study can take another spp",
          "[split]") {
    const MpiSession mpi;  // not under mpirun: a session of one
    const FilmIdentity identity{"ch07_bsdf_refraction", "cornell.json", 1, "", 4, 4, 64, 1};
    RenderSettings settings;
    settings.width = settings.height = 4;
    settings.samples_per_pixel = 64;
    plan_split(SplitOptions{}, identity, mpi, settings);
    CHECK_FALSE(settings.samples.has_value());
    // Chapter 07's depth study renders its reference with the run's settings at 4096 spp: all 4096 samples,
    // not samples 0:64 of them (what a range left set from the run's 64 made it take).
    settings.samples_per_pixel = 4096;
    CHECK(samples_taken(settings).size() == 4096);
    // A piece keeps its range.
    RenderSettings piece = settings;
    piece.samples_per_pixel = 64;
    SplitOptions options;
    options.samples = "8:24";
    plan_split(options, identity, mpi, piece);
    REQUIRE(piece.samples.has_value());
    CHECK(piece.samples->first == 8);
    CHECK(piece.samples->end == 24);
}

TEST_CASE("A scene's fingerprint covers its textures' texels and its meshes' normals and texture coordinates",
          "[split]") {
    // Pieces rendered with another texture image, or a mesh with other vn or vt lines, were merged and
    // resumed as one render: only the scene file, mesh positions and triangles and the environment counted.
    const fs::path textured = scene_path("ch04_textured.json"), smooth = scene_path("ch04_smooth_mesh.json");
    const Scene wood = load_scene(textured), torus = load_scene(smooth);
    const std::uint64_t wood_print = scene_fingerprint(wood, textured);
    const std::uint64_t torus_print = scene_fingerprint(torus, smooth);
    CHECK(scene_fingerprint(wood, textured) == wood_print);  // the same files: the same fingerprint

    const auto with_texture = [&](auto change) {
        Scene scene = wood;
        for (Material& m : scene.materials) {
            for (Material::Textured& given : m.textures) {
                auto* image = std::get_if<ImageTextureDesc>(&given.texture.pattern);
                if (!image) continue;
                TextureImage texels = *image->image;
                change(texels);
                image->image = std::make_shared<const TextureImage>(texels);
            }
        }
        return scene_fingerprint(scene, textured);
    };
    CHECK(with_texture([](TextureImage& t) { t.texels[5].g += Real(0.25); }) != wood_print);
    CHECK(with_texture([](TextureImage& t) { t.width *= 2, t.height /= 2; }) != wood_print);

    const auto with_mesh = [&](auto change) {
        Scene scene = torus;
        for (Shape& shape : scene.shapes) {
            if (auto* mesh = std::get_if<MeshShape>(&shape.geometry)) change(*mesh);
        }
        return scene_fingerprint(scene, smooth);
    };
    CHECK(with_mesh([](MeshShape& m) { m.normals[3].x = -m.normals[3].x; }) != torus_print);
    CHECK(with_mesh([](MeshShape& m) { m.normal_corners[0][1] = m.normal_corners[0][0]; }) != torus_print);
    CHECK(with_mesh([](MeshShape& m) { m.texture_coordinates[2].x += Real(0.5); }) != torus_print);
    CHECK(with_mesh([](MeshShape& m) { m.texture_corners[0][1] = m.texture_corners[0][0]; }) != torus_print);
}
