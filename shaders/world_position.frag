// world_position.frag: the visible point of every camera pixel, for the ray-traced ground truth
// (framework/truth/visible_points.*). Drawn with scene.vert and the lighting pass's camera and
// depth test, so it sees exactly what the lighting pass shades.
in vec3 vWorldPosition;
in vec3 vWorldNormal;

layout(location = 0) out vec4 outPosition;        // world position, w = 1 where covered
layout(location = 1) out vec4 outShadingNormal;   // interpolated normal, as lighting.frag uses
layout(location = 2) out vec4 outGeometricNormal; // the triangle's own plane normal

void main() {
    outPosition = vec4(vWorldPosition, 1.0);
    outShadingNormal = vec4(normalize(vWorldNormal), 0.0);
    // World position is affine over a triangle, and the 2x2 quad's helper lanes interpolate the
    // same triangle, so these derivatives span its plane: the flat face normal, which decides
    // whether the face itself hides the light (the tessellated terminator).
    vec3 g = cross(dFdx(vWorldPosition), dFdy(vWorldPosition));
    outGeometricNormal = vec4(length(g) > 0.0 ? normalize(g) : vec3(0.0), 0.0);
}
