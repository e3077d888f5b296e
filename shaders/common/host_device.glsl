// Structs and binding points shared by C++ and GLSL, declared once. C++ includes this file (through
// viz/render/host_device.h) with __cplusplus defined; GLSL includes it as "common/host_device.glsl".
// Every block member is a vec4, ivec4 or mat4, so std430 and the C++ layout agree without hidden padding
// (checked by the static_asserts on sizes and offsets in viz/render/host_device.h, and on the GPU by
// RenderLights.GpuLightAndMaterialLayoutsMatchGlsl in tests/gl/render_lights_test.cpp). No bool.
#ifndef HOST_DEVICE_GLSL
#define HOST_DEVICE_GLSL

#ifdef __cplusplus
// glm comes from viz/render/host_device.h: the GLSL include resolver expands every #include line,
// whatever the #if around it, so this file includes nothing for C++.
namespace viz::render::hd {
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
#define VIZ_HD_CONST inline constexpr int
#else
#define VIZ_HD_CONST const int
#endif

// ---- binding points (fixed; techniques use SSBO bindings and texture units from kFirst* on) ----
VIZ_HD_CONST kBindingMaterials = 0;         // SSBO: GpuMaterial materials[]
VIZ_HD_CONST kBindingLights = 1;            // SSBO: GpuLight lights[] (std430)
VIZ_HD_CONST kBindingWorkCounters = 3;      // SSBO: work counters, only with COUNT_WORK (common/work_counters.glsl)
VIZ_HD_CONST kFirstFreeSsboBinding = 4;

// The same light buffer is also bound as a uniform block (std140 and std430 agree for GpuLight: every
// member is 16-byte aligned and the size is a multiple of 16). common/lights.glsl reads it as a uniform
// block: on llvmpipe a light loop over a UBO ran 3.8x faster than over the SSBO (surface pass, 19 lights,
// 160x120, machine shared with builds: 69 ms vs 263 ms). A uniform block needs a fixed size, hence kMaxGpuLights (48 KB).
VIZ_HD_CONST kBindingLightsUniform = 1;     // UBO: GpuLight gLights[kMaxGpuLights]
VIZ_HD_CONST kBindingMedium = 2;            // UBO: GpuMedium (common/medium.glsl)
VIZ_HD_CONST kFirstFreeUboBinding = 3;
VIZ_HD_CONST kMaxGpuLights = 256;           // lights after area lights became VPLs

VIZ_HD_CONST kUnitMaterialTextures = 0;     // sampler2DArray, RGBA8 sRGB bytes: base colour + emission
VIZ_HD_CONST kUnitCookies = 1;              // sampler2DArray, RGBA8 sRGB bytes: spot cookies
VIZ_HD_CONST kUnitShadow2D = 2;             // sampler2DArray, R32F: spot and directional shadow maps
VIZ_HD_CONST kUnitShadowCube = 3;           // sampler2DArray, R32F: point-light cubes, 6 layers each
VIZ_HD_CONST kUnitShadowCubeVpl = 4;        // sampler2DArray, R32F: VPL cubes (smaller), 6 layers each
VIZ_HD_CONST kFirstFreeTextureUnit = 8;

// ---- how far along a ray any light counts (scene/ray_reach.h: kReachMeanFreePaths) ----
VIZ_HD_CONST kReachMeanFreePaths = 60;  // past it the medium passes on less than exp(-60) of any light

// ---- work counters (gl/work_counters.h): what a run costs in units no GPU changes ----
VIZ_HD_CONST kWorkShadowLookups = 0;        // shadow-map visibility queries (one per point and light)
VIZ_HD_CONST kWorkShadowTexels = 1;         // shadow-map texels fetched by those queries
VIZ_HD_CONST kWorkRaySamples = 2;           // brute-force ray samples (integrand evaluations of a march)
VIZ_HD_CONST kWorkClosedFormSegments = 3;   // closed-form airlight integrals of a lit interval
VIZ_HD_CONST kWorkTreeNodes = 4;            // min-max tree nodes visited (minmax)
VIZ_HD_CONST kWorkFragments = 5;            // fragments shaded by a technique's own fragment shaders
VIZ_HD_CONST kWorkVoxelsWritten = 6;        // voxel words written (vsv, ivsv voxelization)
VIZ_HD_CONST kWorkVoxelsRead = 7;           // voxel words read (vsv, ivsv scan and gather)
VIZ_HD_CONST kWorkQuadratureNodes = 8;      // integrand evaluations inside closed-form point-light segments
VIZ_HD_CONST kWorkCounterCount = 9;

// ---- light types (GpuLight::info.x) ----
VIZ_HD_CONST kLightPoint = 0;
VIZ_HD_CONST kLightSpot = 1;
VIZ_HD_CONST kLightDirectional = 2;
VIZ_HD_CONST kLightVpl = 3;  // one node of an area light's quadrature, cosine emission lobe

// The homogeneous medium, one uniform block for every shader (filled by render::MediumBlock): x = sigma_s,
// y = sigma_t, z = g (Henyey-Greenstein), w unused. common/medium.glsl declares the same 16 bytes as three
// floats, which std140 places at offsets 0, 4 and 8.
struct GpuMedium {
    vec4 coefficients;
};

// One material. Colours are linear. Texture layers index the material texture array; a layer whose
// image is smaller than the array uses only the [0, size) corner, hence the per-layer size.
struct GpuMaterial {
    vec4 baseColour;   // baseColorFactor (linear rgba)
    vec4 emissive;    // rgb = emissiveFactor * emissiveStrength (radiance), w unused
    ivec4 layers;     // x base-colour layer (-1: none), y emission layer (-1: none), zw unused
    vec4 layerSize;   // xy base-colour layer size in texels, zw emission layer size in texels
};

// One light. All positions are eye-relative world space (world translated so the eye is at the origin,
// axes unchanged; the translation is done in double on the CPU).
struct GpuLight {
    vec4 position;     // xyz: point, spot, VPL position; w: a VPL's kernel (1: its cell, 0: a point;
                       // lights.glsl, vplHasCell), 1 for other lights
    vec4 direction;    // xyz unit: spot axis / directional travel direction / VPL emitter normal
    vec4 radiant;      // rgb: colour * intensity (point, spot, directional) or VPL weight L_e(uv) * dA
    vec4 spot;         // x KHR scale, y KHR offset, z tan(outer), w cos(outer); a VPL's cell: xyz a corner,
                       // w its area dA (frameX.xyz, frameY.xyz: its edges)
    vec4 frameX;       // xyz cookie frame x (right) axis; w cookie width in texels
    vec4 frameY;       // xyz cookie frame y (up) axis;    w cookie height in texels
    ivec4 info;        // x type (kLight*), y cookie layer (-1: none), z shadow map index (-1: none;
                       // 2D: the layer, cubes: the cube, layers 6z .. 6z+5),
                       // w index of the scene light it comes from
    vec4 shadow;       // xy range of the stored values (near and far plane; directional: depth range),
                       // z bias per texel footprint, w bias constant (scene units; see shadow_map.glsl)
    mat4 shadowMatrix; // eye-relative world -> clip space of the 2D shadow map (spot, directional)
};

#ifdef __cplusplus
}  // namespace viz::render::hd
#endif
#undef VIZ_HD_CONST

#endif  // HOST_DEVICE_GLSL
