#version 450 core
// polyvol/volume.vert: one vertex of a light's polygonal light volume (Billeter et al. 2010, section 4).
// No vertex buffer. Vertex v < uGridVertices belongs to the procedural static grid: triangle v / 3 of
// uGridFaces grids of N x N texel centres, two per quad split along (i, j) -> (i + 1, j + 1), CCW seen
// from the light; later vertices read their key from gExtraKeys (the closure of a 2D grid, the seams of
// a cube, or the adaptive tessellation's triangles; viz/techniques/polyvol/light_volume_mesh.h).
// Output: the eye-relative world position.

#include "polyvol/volume_grid.glsl"

uniform mat4 uViewProj;      // eye-relative world -> camera clip space
uniform int uGridVertices;   // 3 x the procedural grid triangles (0: keys only)

layout(std430, binding = kFirstFreeSsboBinding) readonly buffer ExtraKeys { uint gExtraKeys[]; };

out vec3 vPosition;

#ifdef WIRE_CLIP
// The mesh's orbit view (polyvol.mesh): the volume clipped to the box around the scene and its lights
// (eye-relative), so that a directional light's skirt and far cap, which reach the camera's far plane,
// do not cover the whole view. The caller enables the six clip distances for it; uClipOn = 0 writes
// positive distances for the other wireframe modes (llvmpipe drew nothing there with the box's distances
// written and the planes not enabled).
uniform vec3 uClipMin, uClipMax;
uniform int uClipOn;
out gl_PerVertex {
    vec4 gl_Position;
    float gl_ClipDistance[6];
};
#endif

void main() {
    GpuLight L = gLights[uLightIndex];
    int v = gl_VertexID;
    vec3 p;
    if (v < uGridVertices) {
        int quadsPerFace = (uMapSize - 1) * (uMapSize - 1);
        int triangle = v / 3;
        int corner = v % 3;
        int quad = triangle >> 1;
        int face = quad / quadsPerFace;
        int q = quad % quadsPerFace;
        int i = q % (uMapSize - 1);
        int j = q / (uMapSize - 1);
        // (00, 10, 11) and (00, 11, 01): counter-clockwise in the map's ndc, i.e. seen from the light.
        const ivec2 kLower[3] = ivec2[3](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1));
        const ivec2 kUpper[3] = ivec2[3](ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
        ivec2 offset = (triangle & 1) == 0 ? kLower[corner] : kUpper[corner];
        p = gridPosition(L, face, i + offset.x, j + offset.y);
    } else {
        p = keyPosition(L, gExtraKeys[v - uGridVertices]);
    }
    vPosition = p;
    gl_Position = uViewProj * vec4(p, 1.0);
#ifdef WIRE_CLIP
    for (int k = 0; k < 3; ++k) {
        gl_ClipDistance[2 * k] = uClipOn != 0 ? p[k] - uClipMin[k] : 1.0;
        gl_ClipDistance[2 * k + 1] = uClipOn != 0 ? uClipMax[k] - p[k] : 1.0;
    }
#endif
}
