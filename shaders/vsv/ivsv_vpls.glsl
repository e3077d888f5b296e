// The VPLs of ivsv and their epipolar spaces (one std430 array, filled by IvsvTechnique; every member a
// vec4 or ivec4 so that C++ and GLSL agree, see the static_assert in ivsv_technique.h).
#ifndef VSV_IVSV_VPLS_GLSL
#define VSV_IVSV_VPLS_GLSL

#include "vsv/epipolar.glsl"

struct IvsvVpl {
    vec4 position;   // xyz eye-relative
    vec4 normal;     // xyz emitter normal (the hemisphere's axis)
    vec4 tangent;    // xyz hemisphere frame x
    vec4 bitangent;  // xyz hemisphere frame y
    vec4 weight;     // rgb L_e dA, w dA / pi (the squared radius of a disc of the VPL's area; 0: a point)
    vec4 epiB;       // xyz baseline, w eye-VPL distance D
    vec4 epiU;
    vec4 epiV;
    vec4 epiAlpha;   // alpha0, dAlpha
    vec4 epiTheta;   // thetaCentre, thetaHalf, dTheta, 1 = full circle
    vec4 epiPhi;     // phi0, dPhi
    ivec4 tile;      // xy origin of its epipolar grid tile, zw origin of its shadow-map tile
    ivec4 extra;     // x cube index of its shadow map (mode=naive)
    vec4 cellCorner; // vpl_layout=grid with vpl_kernel=cell: xyz eye-relative corner of its cell of the
                     // emitter, w its area dA (0: no cell)
    vec4 cellU;      // xyz the cell's edges from the corner
    vec4 cellV;
};

layout(std430, binding = 4) readonly buffer IvsvVplBlock { IvsvVpl gVpls[]; };

EpiSpace vplSpace(IvsvVpl v, ivec3 cells) {
    return EpiSpace(v.epiB.xyz, v.epiU.xyz, v.epiV.xyz, v.epiB.w, cells, v.epiAlpha.xy, v.epiTheta.xyz,
                    v.epiPhi.xy, v.epiTheta.w != 0.0);
}

#endif  // VSV_IVSV_VPLS_GLSL
