#include "gl_program.hpp"

#include <stdexcept>

namespace rt {
namespace {

std::string shader_log(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str();
}

std::string program_log(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.c_str();
}

}  // namespace

GlProgram::GlProgram(std::span<const ShaderStage> stages) : id_(glCreateProgram()) {
    std::vector<GLuint> shaders;
    for (const ShaderStage& stage : stages) {
        const GLuint shader = glCreateShader(stage.type);
        const GLchar* text = stage.source.data();
        const GLint length = GLint(stage.source.size());
        glShaderSource(shader, 1, &text, &length);
        glCompileShader(shader);
        GLint ok = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            const std::string log = shader_log(shader);
            glDeleteShader(shader);
            for (GLuint s : shaders) glDeleteShader(s);
            glDeleteProgram(id_);
            throw std::runtime_error("the driver did not compile " + std::string(stage.name) + ": " + log);
        }
        glAttachShader(id_, shader);
        shaders.push_back(shader);
    }
    glLinkProgram(id_);
    for (GLuint s : shaders) glDeleteShader(s);
    GLint linked = 0;
    glGetProgramiv(id_, GL_LINK_STATUS, &linked);
    if (!linked) {
        const std::string log = program_log(id_);
        glDeleteProgram(id_);
        throw std::runtime_error("the driver did not link the shaders: " + log);
    }
}

GlProgram::~GlProgram() {
    glDeleteProgram(id_);
}

void GlProgram::set(const char* name, int value) const {
    glProgramUniform1i(id_, location(name), value);
}
void GlProgram::set(const char* name, unsigned value) const {
    glProgramUniform1ui(id_, location(name), value);
}
void GlProgram::set(const char* name, float value) const {
    glProgramUniform1f(id_, location(name), value);
}
void GlProgram::set(const char* name, bool value) const {
    glProgramUniform1i(id_, location(name), value ? 1 : 0);
}
void GlProgram::set(const char* name, float x, float y) const {
    glProgramUniform2f(id_, location(name), x, y);
}
void GlProgram::set(const char* name, float x, float y, float z) const {
    glProgramUniform3f(id_, location(name), x, y, z);
}
void GlProgram::set(const char* name, int x, int y) const {
    glProgramUniform2i(id_, location(name), x, y);
}
void GlProgram::set(const char* name, unsigned x, unsigned y) const {
    glProgramUniform2ui(id_, location(name), x, y);
}

GlBuffer::GlBuffer(const void* data, std::size_t bytes) {
    glCreateBuffers(1, &id_);
    // A buffer of 0 bytes cannot be bound: an empty list gets 16 bytes nobody reads.
    glNamedBufferData(id_, GLsizeiptr(bytes > 0 ? bytes : 16), bytes > 0 ? data : nullptr, GL_DYNAMIC_DRAW);
}

GlBuffer::~GlBuffer() {
    glDeleteBuffers(1, &id_);
}

void GlBuffer::zero() const {
    const GLuint nothing = 0;
    glClearNamedBufferData(id_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &nothing);
}

}  // namespace rt
