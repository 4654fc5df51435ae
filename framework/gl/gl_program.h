// GlProgram: a linked GLSL program (graphics or compute) built from ShaderLibrary files, with
// uniform setters by name. A compile or link failure throws ShaderError whose message names
// the real files and lines, followed by the driver's complete log.
#pragma once

#include "gl_api.h"
#include "shader_source.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

class GlProgram {
public:
    GlProgram() = default;
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;
    GlProgram(GlProgram&& other) noexcept : id_(other.id_) { other.id_ = 0; }
    GlProgram& operator=(GlProgram&& other) noexcept;
    ~GlProgram();

    static GlProgram graphics(const ShaderLibrary& lib, const std::string& vertexFile,
                              const std::string& fragmentFile,
                              const std::vector<std::string>& defines);
    static GlProgram compute(const ShaderLibrary& lib, const std::string& computeFile,
                             const std::vector<std::string>& defines);

    GLuint id() const { return id_; }
    void use() const { gl::UseProgram(id_); }
    glm::ivec3 workGroupSize() const;  // compute programs only
    // The value of an int uniform, e.g. one the shader declares with an initializer to tell
    // the framework something; `fallback` if the program has no such uniform.
    int getInt(const char* name, int fallback) const;

    // Setters ignore names the program does not use (location -1), as GL does.
    void set(const char* name, int v) const;
    void set(const char* name, float v) const;
    void set(const char* name, glm::ivec2 v) const;
    void set(const char* name, glm::vec2 v) const;
    void set(const char* name, glm::vec3 v) const;
    void set(const char* name, const glm::mat4& m) const;
    void setArray(const char* name, const std::vector<glm::vec3>& v) const;
    void setArray(const char* name, const std::vector<glm::vec4>& v) const;
    void setArray(const char* name, const std::vector<glm::vec2>& v) const;
    void setArray(const char* name, const std::vector<float>& v) const;
    void setArray(const char* name, const std::vector<int>& v) const;
    void setArray(const char* name, const std::vector<glm::mat4>& v) const;

private:
    explicit GlProgram(GLuint id) : id_(id) {}
    GLint location(const char* name) const { return gl::GetUniformLocation(id_, name); }
    GLuint id_ = 0;
};

}  // namespace sl
