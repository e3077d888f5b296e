// polyvol/volume_grid.glsl: where a light volume vertex is. A vertex is a key (light_volume_mesh.h): a
// texel (i, j) of a grid face, a cap vertex or the apex; its position comes from the linear-distance
// shadow map (distance to the light; depth dot(p, dir) for a directional light; not z). Shared by the
// volume's vertex shader and the adaptive tessellation's edge map. Eye-relative world space.
#ifndef POLYVOL_VOLUME_GRID_GLSL
#define POLYVOL_VOLUME_GRID_GLSL

#include "common/host_device.glsl"
#include "common/lights.glsl"
#include "common/shadow_map.glsl"

const int kModeSpot = 0;
const int kModeDirectional = 1;
const int kModeCube = 2;

uniform int uMode;
uniform int uMapSize;        // N, texels per side
uniform int uLayer;          // 2D map layer, or cube index (layers 6 uLayer + face)
uniform int uLightIndex;
uniform int uVplCube;        // 1: the cube is a VPL's (area light node), in the VPL cube array
uniform int uKeyStride;      // texels per row of the key space: N (static), N + 1 (adaptive: the virtual
                             // column and row N are clamped onto N - 1, so quads of 2^k texels tile it)
// Spot: the point on the view plane at unit depth for ndc (x, y) is uLightPos + uPlaneOrigin + x uPlaneX + y uPlaneY.
// Directional: the point on the map's near plane is uPlaneOrigin + x uPlaneX + y uPlaneY (eye-relative).
uniform vec3 uPlaneOrigin;
uniform vec3 uPlaneX;
uniform vec3 uPlaneY;
uniform float uNoHit;        // spot, point: distance of empty texels; directional: their depth
uniform float uCapDepth;     // directional: depth of the cap behind the scene
uniform float uSkirt;        // directional: lateral scale of the border ring (covers the camera's reach)
uniform float uCookieMask;   // cookie texels whose brightest channel is below this are dark

// The stored value of texel (i, j) of face `face` (clamped into the map).
float storedValue(int face, int i, int j) {
    i = min(i, uMapSize - 1);
    j = min(j, uMapSize - 1);
    if (uMode == kModeCube) {
        ivec3 t = ivec3(i, j, 6 * uLayer + face);
        return uVplCube != 0 ? texelFetch(uShadowCubeVpl, t, 0).r : texelFetch(uShadowCube, t, 0).r;
    }
    return texelFetch(uShadow2D, ivec3(i, j, uLayer), 0).r;
}

vec2 texelNdc(int i, int j) { return (vec2(min(ivec2(i, j), ivec2(uMapSize - 1))) + 0.5) * (2.0 / float(uMapSize)) - 1.0; }

vec3 apexPosition(GpuLight L) {
    if (uMode != kModeDirectional) return L.position.xyz;
    vec3 dir = L.direction.xyz;
    return uPlaneOrigin + dir * (uCapDepth - dot(uPlaneOrigin, dir));
}

// Point of a directional map's column (i, j) at depth `depth`; the border ring is pushed out by uSkirt.
vec3 directionalPoint(GpuLight L, int i, int j, float depth) {
    vec2 ndc = texelNdc(i, j);
    bool border = i == 0 || j == 0 || i >= uMapSize - 1 || j >= uMapSize - 1;
    if (border) ndc *= uSkirt;
    vec3 q = uPlaneOrigin + ndc.x * uPlaneX + ndc.y * uPlaneY;
    vec3 dir = L.direction.xyz;
    return q + dir * (depth - dot(q, dir));
}

vec3 gridPosition(GpuLight L, int face, int i, int j) {
    float stored = storedValue(face, i, j);
    bool empty = stored >= 1.0e29;  // cleared texel: nothing in front of the far plane
    if (uMode == kModeDirectional) return directionalPoint(L, i, j, empty ? uNoHit : stored);
    vec3 dir;
    if (uMode == kModeCube) {
        vec3 forward, up;
        cubeFaceBasis(face, forward, up);
        vec3 right = cross(forward, up);
        vec3 trueUp = cross(right, forward);
        vec2 ndc = texelNdc(i, j);
        dir = normalize(forward + ndc.x * right + ndc.y * trueUp);
    } else {
        vec2 ndc = texelNdc(i, j);
        dir = normalize(uPlaneOrigin + ndc.x * uPlaneX + ndc.y * uPlaneY);
#ifndef LIGHTS_NO_SPOT
        // Outside the cone (A_spot = 0) or under a dark cookie texel: no light leaves in this direction,
        // so the vertex goes to the light and the volume follows the cone.
        if (spotAttenuation(L, dir) == 0.0) return L.position.xyz;
#ifndef LIGHTS_NO_COOKIE
        vec3 cookie = spotCookie(L, dir);
        if (max(cookie.r, max(cookie.g, cookie.b)) < uCookieMask) return L.position.xyz;
#endif
#endif
    }
    return L.position.xyz + dir * (empty ? uNoHit : stored);
}

vec3 keyPosition(GpuLight L, uint key) {
    if (key == 0xFFFFFFFFu) return apexPosition(L);
    uint n2 = uint(uKeyStride * uKeyStride);
    int face = int(key / n2);
    uint rest = key % n2;
    int i = int(rest % uint(uKeyStride));
    int j = int(rest / uint(uKeyStride));
    if (face == 6) {  // cap vertex under (i, j); for spot and point lights the light itself
        if (uMode != kModeDirectional) return L.position.xyz;
        return directionalPoint(L, i, j, uCapDepth);
    }
    return gridPosition(L, face, i, j);
}


// The depth of the vertex at texel (i, j) along its map's axis, what the adaptive tessellation's edge map
// differentiates: a directional map's depth, affine in the texel on a plane receiver; or the depth along
// a spot's axis or a cube face's forward, whose reciprocal is (a perspective projection, as the paper's
// depth buffer). Vertices at the light (dark spot texels) are at 0.
float gridAxisDepth(GpuLight L, int face, int i, int j) {
    vec3 p = gridPosition(L, face, i, j);
    if (uMode == kModeDirectional) return dot(p, L.direction.xyz);
    vec3 axis = L.direction.xyz;
    if (uMode == kModeCube) {
        vec3 up;
        cubeFaceBasis(face, axis, up);
    }
    return dot(p - L.position.xyz, axis);
}

#endif  // POLYVOL_VOLUME_GRID_GLSL
