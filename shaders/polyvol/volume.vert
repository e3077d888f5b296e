#version 450 core
// polyvol/volume.vert: one vertex of a light's polygonal light volume (Billeter et al. 2010, section 4).
// No vertex buffer. The procedural static grid (uGridRows = 1) is drawn one row of quads per instance:
// row r = gl_InstanceID + uRowOffset is row j = r % (N - 1) of face r / (N - 1), and the element buffer's
// vertex v is texel (v % N, j + v / N), two triangles per quad split along (i, j) -> (i + 1, j + 1), CCW
// seen from the light (PolyvolTechnique::drawMesh). Indexed, a texel's position is computed about once
// per row instead of once per triangle corner (six times). Otherwise (uGridRows = 0) vertex v reads its
// key from gExtraKeys (the closure of a 2D grid, the seams of a cube, or the adaptive tessellation's
// triangles; viz/techniques/polyvol/light_volume_mesh.h).
// Output: the eye-relative world position.

#include "polyvol/volume_grid.glsl"

uniform mat4 uViewProj;      // eye-relative world -> camera clip space
uniform int uGridRows;       // 1: instanced rows of the procedural grid; 0: keys from gExtraKeys
uniform int uRowOffset;      // the first row of this draw (a draw that stops inside the grid)

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
    if (uGridRows != 0) {
        int row = gl_InstanceID + uRowOffset;
        int face = row / (uMapSize - 1);
        int j = row % (uMapSize - 1);
        p = gridPosition(L, face, v % uMapSize, j + v / uMapSize);
    } else {
        p = keyPosition(L, gExtraKeys[v]);
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
