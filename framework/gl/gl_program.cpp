// GlProgram: compilation, linking and error mapping (see gl_program.h).
#include "gl_program.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>

namespace sl {
namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    gl::GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::max(length, 1), '\0');
    gl::GetShaderInfoLog(shader, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

std::string programLog(GLuint program) {
    GLint length = 0;
    gl::GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::max(length, 1), '\0');
    gl::GetProgramInfoLog(program, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

GLuint compileShader(GLenum type, const AssembledShader& src) {
    GLuint shader = gl::CreateShader(type);
    const char* text = src.text.c_str();
    gl::ShaderSource(shader, 1, &text, nullptr);
    gl::CompileShader(shader);
    GLint ok = GL_FALSE;
    gl::GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::string log = shaderLog(shader);
        gl::DeleteShader(shader);
        std::string first;
        std::string mapped = src.mapLog(log, &first);
        if (first.empty() && !src.fileNames.empty()) first = src.fileNames.front();
        throw ShaderError(mapped + "--- driver log (" + src.fileNames.front() + ") ---\n" + log,
                          first);
    }
    return shader;
}

GLuint link(const std::vector<GLuint>& shaders, const std::string& what) {
    GLuint program = gl::CreateProgram();
    for (GLuint s : shaders) gl::AttachShader(program, s);
    gl::LinkProgram(program);
    for (GLuint s : shaders) gl::DeleteShader(s);
    GLint ok = GL_FALSE;
    gl::GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string log = programLog(program);
        gl::DeleteProgram(program);
        throw ShaderError(what + ": link error\n--- driver log ---\n" + log, what);
    }
    return program;
}

}  // namespace

GlProgram& GlProgram::operator=(GlProgram&& other) noexcept {
    if (this != &other) {
        if (id_) gl::DeleteProgram(id_);
        id_ = other.id_;
        other.id_ = 0;
    }
    return *this;
}

GlProgram::~GlProgram() {
    if (id_) gl::DeleteProgram(id_);
}

GlProgram GlProgram::graphics(const ShaderLibrary& lib, const std::string& vertexFile,
                              const std::string& fragmentFile,
                              const std::vector<std::string>& defines) {
    auto vs = lib.assemble(vertexFile, defines);
    auto fs = lib.assemble(fragmentFile, defines);
    GLuint v = compileShader(GL_VERTEX_SHADER, vs);
    GLuint f = 0;
    try {
        f = compileShader(GL_FRAGMENT_SHADER, fs);
    } catch (...) {
        gl::DeleteShader(v);
        throw;
    }
    return GlProgram(link({v, f}, vs.fileNames.front() + " + " + fs.fileNames.front()));
}

GlProgram GlProgram::compute(const ShaderLibrary& lib, const std::string& computeFile,
                             const std::vector<std::string>& defines) {
    auto cs = lib.assemble(computeFile, defines);
    return GlProgram(link({compileShader(GL_COMPUTE_SHADER, cs)}, cs.fileNames.front()));
}

glm::ivec3 GlProgram::workGroupSize() const {
    GLint size[3] = {1, 1, 1};
    gl::GetProgramiv(id_, GL_COMPUTE_WORK_GROUP_SIZE, size);
    return {size[0], size[1], size[2]};
}

int GlProgram::getInt(const char* name, int fallback) const {
    const GLint loc = location(name);
    if (loc < 0) return fallback;
    GLint value = fallback;
    gl::GetUniformiv(id_, loc, &value);
    return value;
}

void GlProgram::set(const char* n, int v) const { gl::ProgramUniform1i(id_, location(n), v); }
void GlProgram::set(const char* n, float v) const { gl::ProgramUniform1f(id_, location(n), v); }
void GlProgram::set(const char* n, glm::ivec2 v) const {
    gl::ProgramUniform2i(id_, location(n), v.x, v.y);
}
void GlProgram::set(const char* n, glm::vec2 v) const {
    gl::ProgramUniform2f(id_, location(n), v.x, v.y);
}
void GlProgram::set(const char* n, glm::vec3 v) const {
    gl::ProgramUniform3fv(id_, location(n), 1, &v.x);
}
void GlProgram::set(const char* n, const glm::mat4& m) const {
    gl::ProgramUniformMatrix4fv(id_, location(n), 1, GL_FALSE, glm::value_ptr(m));
}
void GlProgram::setArray(const char* n, const std::vector<glm::vec3>& v) const {
    if (!v.empty()) gl::ProgramUniform3fv(id_, location(n), GLsizei(v.size()), &v[0].x);
}
void GlProgram::setArray(const char* n, const std::vector<glm::vec4>& v) const {
    if (!v.empty()) gl::ProgramUniform4fv(id_, location(n), GLsizei(v.size()), &v[0].x);
}
void GlProgram::setArray(const char* n, const std::vector<glm::vec2>& v) const {
    if (!v.empty()) gl::ProgramUniform2fv(id_, location(n), GLsizei(v.size()), &v[0].x);
}
void GlProgram::setArray(const char* n, const std::vector<float>& v) const {
    if (!v.empty()) gl::ProgramUniform1fv(id_, location(n), GLsizei(v.size()), v.data());
}
void GlProgram::setArray(const char* n, const std::vector<int>& v) const {
    if (!v.empty()) gl::ProgramUniform1iv(id_, location(n), GLsizei(v.size()), v.data());
}
void GlProgram::setArray(const char* n, const std::vector<glm::mat4>& v) const {
    if (!v.empty())
        gl::ProgramUniformMatrix4fv(id_, location(n), GLsizei(v.size()), GL_FALSE,
                                    glm::value_ptr(v[0]));
}

}  // namespace sl
