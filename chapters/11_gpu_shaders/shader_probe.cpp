#include "shader_probe.hpp"

#include <bit>

#include "embedded_shaders.hpp"
#include "gl_program.hpp"

namespace rt {

struct ShaderProbe::State {
    explicit State(const GpuScene& scene)
        : program(std::vector<ShaderStage>{{GL_COMPUTE_SHADER, "probe.comp", shaders::k_probe_comp}}),
          nodes(scene.nodes),
          primitives(scene.primitives) {
        program.set("node_count", std::uint32_t(scene.nodes.size()));
        program.set("plane_first", scene.plane_first);
        program.set("plane_count", scene.plane_count);
    }

    // Runs the probe on `input` (uvec4s), `outputs` uvec4s back per entry.
    std::vector<GpuUvec4> run(int mode, const std::vector<GpuUvec4>& input, std::size_t entries) const {
        const GlBuffer in(input);
        const std::vector<GpuUvec4> zeros(2 * entries, GpuUvec4(0));
        const GlBuffer out(zeros);
        nodes.bind(0);
        primitives.bind(1);
        in.bind(5);
        out.bind(6);
        program.set("probe_mode", mode);
        program.set("probe_count", std::uint32_t(entries));
        program.use();
        glDispatchCompute(GLuint((entries + 63) / 64), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<GpuUvec4> result(2 * entries);
        out.read(result.data(), result.size() * sizeof(GpuUvec4));
        return result;
    }

    GlProgram program;
    GlBuffer nodes, primitives;
};

ShaderProbe::ShaderProbe(const GlContext&, const GpuScene& scene) : state_(std::make_unique<State>(scene)) {}
ShaderProbe::~ShaderProbe() = default;

std::vector<ProbeRandom> ShaderProbe::random_numbers(const std::vector<Query>& queries,
                                                     std::uint64_t seed) const {
    state_->program.set("seed_bits", std::uint32_t(seed), std::uint32_t(seed >> 32u));
    std::vector<GpuUvec4> input;
    for (const Query& q : queries) {
        input.emplace_back(std::uint32_t(q.pixel), std::uint32_t(q.pixel >> 32u), std::uint32_t(q.sample),
                           std::uint32_t(q.sample >> 32u));
    }
    const std::vector<GpuUvec4> out = state_->run(0, input, queries.size());
    std::vector<ProbeRandom> result(queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i) {
        for (int k = 0; k < 4; ++k) {
            result[i].words[std::size_t(k)] = out[2 * i][k];
            result[i].reals[std::size_t(k)] = std::bit_cast<float>(out[2 * i + 1][k]);
        }
    }
    return result;
}

std::vector<ProbeHit> ShaderProbe::nearest_hits(const std::vector<Ray>& rays, float t_max) const {
    std::vector<GpuUvec4> input;
    for (const Ray& r : rays) {
        input.emplace_back(
            std::bit_cast<std::uint32_t>(float(r.origin.x)), std::bit_cast<std::uint32_t>(float(r.origin.y)),
            std::bit_cast<std::uint32_t>(float(r.origin.z)), std::bit_cast<std::uint32_t>(t_max));
        input.emplace_back(std::bit_cast<std::uint32_t>(float(r.direction.x)),
                           std::bit_cast<std::uint32_t>(float(r.direction.y)),
                           std::bit_cast<std::uint32_t>(float(r.direction.z)), 0u);
    }
    const std::vector<GpuUvec4> out = state_->run(1, input, rays.size());
    std::vector<ProbeHit> result(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const GpuUvec4 a = out[2 * i], b = out[2 * i + 1];
        result[i] = {a.x != 0,
                     std::bit_cast<float>(a.y),
                     a.z,
                     a.w != 0,
                     Vec3(std::bit_cast<float>(b.x), std::bit_cast<float>(b.y), std::bit_cast<float>(b.z)),
                     b.w};
    }
    return result;
}

}  // namespace rt
