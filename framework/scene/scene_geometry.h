// SceneGeometry: the meshes of all of a scene's objects in one vertex and one index buffer,
// with each object's placement and world bounds, ready to draw for any view.
#pragma once

#include "gl_program.h"
#include "gpu_resources.h"
#include "mesh.h"
#include "scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace sl {

class SceneGeometry {
public:
    explicit SceneGeometry(const Scene& scene);

    // Draws every object (or only shadow casters), setting uModel, uNormalMatrix and, with
    // `material`, uAlbedo, uSpecular and uShininess on `program`.
    void draw(const GlProgram& program, bool castersOnly, bool material) const;

    const std::vector<Bounds>& bounds() const { return bounds_; }  // per object, world space

private:
    struct Draw {
        GLsizei count;
        size_t firstIndex;
        GLint baseVertex;
        glm::mat4 model;
        const Object* object;
    };
    BufferHandle vertices_, indices_;
    VertexArrayHandle vao_;
    std::vector<Draw> draws_;
    std::vector<Bounds> bounds_;
};

}  // namespace sl
