// scene.vert: places a mesh in the world and projects it, for the shadow pass (light's view)
// and the lighting pass (camera's view).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uModel;           // object to world
uniform mat4 uNormalMatrix;    // inverse transpose of uModel
uniform mat4 uViewProjection;  // world to clip, of the light or the camera

out vec3 vWorldPosition;
out vec3 vWorldNormal;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = mat3(uNormalMatrix) * aNormal;
    gl_Position = uViewProjection * world;
}
