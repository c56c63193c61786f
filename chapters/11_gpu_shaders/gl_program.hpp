// The few OpenGL objects the renderer needs, each owned by a small class: a linked program (its stages
// compiled from source, the driver's log in the error), a shader storage buffer, and a uniform setter that
// names the uniform it could not find.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gl_api.hpp"

namespace rt {

// The version line, the shared files and the stage's main, as CMake composed them (embedded_shaders.hpp).
struct ShaderStage {
    GLenum type;  // GL_COMPUTE_SHADER, GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
    std::string_view name;
    std::string_view source;
};

class GlProgram {
  public:
    // Compiles and links; throws std::runtime_error with the driver's log on failure.
    explicit GlProgram(std::span<const ShaderStage> stages);
    ~GlProgram();
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;

    GLuint id() const { return id_; }
    void use() const { glUseProgram(id_); }
    // Uniforms of the program in use; a uniform the compiler removed (unused in this stage) is skipped.
    void set(const char* name, int value) const;
    void set(const char* name, unsigned value) const;
    void set(const char* name, float value) const;
    void set(const char* name, bool value) const;
    void set(const char* name, float x, float y) const;
    void set(const char* name, float x, float y, float z) const;
    void set(const char* name, int x, int y) const;
    void set(const char* name, unsigned x, unsigned y) const;

  private:
    GLint location(const char* name) const { return glGetUniformLocation(id_, name); }
    GLuint id_ = 0;
};

// A buffer of bytes bound to a shader storage binding point.
class GlBuffer {
  public:
    GlBuffer(const void* data, std::size_t bytes);
    template <typename T>
    explicit GlBuffer(const std::vector<T>& items) : GlBuffer(items.data(), items.size() * sizeof(T)) {}
    ~GlBuffer();
    GlBuffer(const GlBuffer&) = delete;
    GlBuffer& operator=(const GlBuffer&) = delete;

    void bind(GLuint binding) const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, id_); }
    void read(void* data, std::size_t bytes) const {
        glGetNamedBufferSubData(id_, 0, GLsizeiptr(bytes), data);
    }
    void zero() const;

  private:
    GLuint id_ = 0;
};

}  // namespace rt
