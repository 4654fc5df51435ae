// SceneGeometry: upload and drawing of a scene's meshes (see scene_geometry.h).
#include "scene_geometry.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cstdint>

namespace sl {

SceneGeometry::SceneGeometry(const Scene& scene) {
    std::vector<float> vdata;  // interleaved position, normal
    std::vector<std::uint32_t> idata;
    for (const Object& object : scene.objects) {
        Mesh mesh = buildMesh(object, scene);
        glm::mat4 model = objectToWorld(object);
        draws_.push_back({GLsizei(mesh.indices.size()), idata.size(), GLint(vdata.size() / 6),
                          model, &object});
        bounds_.push_back(worldBounds(mesh, model));
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::vec3& p = mesh.positions[i];
            const glm::vec3& n = mesh.normals[i];
            vdata.insert(vdata.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
        }
        idata.insert(idata.end(), mesh.indices.begin(), mesh.indices.end());
    }
    if (vdata.empty()) return;
    vertices_ = createBuffer(vdata.data(), GLsizeiptr(vdata.size() * sizeof(float)));
    indices_ = createBuffer(idata.data(), GLsizeiptr(idata.size() * sizeof(std::uint32_t)));
    GLuint id = 0;
    gl::CreateVertexArrays(1, &id);
    vao_ = VertexArrayHandle(id);
    gl::VertexArrayVertexBuffer(id, 0, vertices_.id(), 0, 6 * sizeof(float));
    gl::VertexArrayElementBuffer(id, indices_.id());
    for (GLuint a = 0; a < 2; ++a) {  // 0: position, 1: normal (scene.vert)
        gl::EnableVertexArrayAttrib(id, a);
        gl::VertexArrayAttribFormat(id, a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
        gl::VertexArrayAttribBinding(id, a, 0);
    }
}

void SceneGeometry::draw(const GlProgram& p, bool castersOnly, bool material) const {
    if (!vao_) return;
    gl::BindVertexArray(vao_.id());
    for (const Draw& d : draws_) {
        if (castersOnly && !d.object->castsShadows) continue;
        p.set("uModel", d.model);
        p.set("uNormalMatrix", glm::inverseTranspose(d.model));
        if (material) {
            p.set("uAlbedo", d.object->color);
            p.set("uSpecular", d.object->specular);
            p.set("uShininess", d.object->shininess);
        }
        gl::DrawElementsBaseVertex(GL_TRIANGLES, d.count, GL_UNSIGNED_INT,
                                   reinterpret_cast<const void*>(d.firstIndex * 4),
                                   d.baseVertex);
    }
    gl::BindVertexArray(0);
}

}  // namespace sl
