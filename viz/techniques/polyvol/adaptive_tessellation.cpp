#include "techniques/polyvol/adaptive_tessellation.h"

#include <algorithm>
#include <bit>

#include "core/error.h"
#include "render/host_device.h"

namespace viz::polyvol {
namespace {

// Counters block of tess_refine.comp / tess_args.comp: inCount, outCount, triangles, overflow,
// dispatchArgs[3], drawArgs[4].
constexpr std::size_t kCounterWords = 11;
constexpr std::size_t kDispatchOffset = 4 * sizeof(std::uint32_t);
constexpr std::size_t kDrawOffset = 7 * sizeof(std::uint32_t);
// Buffer caps (shared machine): 4 M quads per refinement list, 24 M keys (8 M triangles). Overflow is
// counted and reported; the mesh is then cut short (the crack detector shows it).
constexpr std::uint32_t kMaxListEntries = 4u << 20;
constexpr std::uint32_t kMaxKeys = 24u << 20;

// Texture units past the scene's and the volume pass's (hd::kFirstFreeTextureUnit + 0, + 1).
constexpr GLuint kUnitEdges = 10, kUnitFlags = 11;
static_assert(kUnitEdges >= render::hd::kFirstFreeTextureUnit + 2);
constexpr GLuint kBindingCounters = 4, kBindingIn = 5, kBindingOut = 6, kBindingKeys = 7, kBindingGroups = 8;
// tess_refine.comp's work group size: one (children, triangles) pair per group in mGroups.
constexpr std::uint32_t kRefineGroup = 64;

}  // namespace

std::size_t AdaptiveTessellation::drawOffset() { return kDrawOffset; }

int AdaptiveTessellation::refinementLevels(int mapSize) {
    return std::max(0, std::countr_zero(unsigned(std::max(mapSize, 1))) - kCoarseSteps);
}

void AdaptiveTessellation::build(const VolumeGrid& grid, EdgeMeasure measure, double threshold, int stopLevel,
                                 const gl::ShaderDefines& defines, const std::string& definesKey) {
    const int n = grid.mapSize;
    if (n < 16 || !std::has_single_bit(unsigned(n)))
        throw InputError("tessellation=adaptive needs a power-of-two shadow_map (got " + std::to_string(n) + ")");
    const int top = std::countr_zero(unsigned(n));  // log2 N

    if (!mLevelsProgram) {
        mLevelsProgram = gl::Program::compile({.stages = {"polyvol/tess_levels.comp"}, .label = "polyvol.tess_levels"});
        mRefineProgram = gl::Program::compile({.stages = {"polyvol/tess_refine.comp"}, .label = "polyvol.tess_refine"});
        mArgsProgram = gl::Program::compile({.stages = {"polyvol/tess_args.comp"}, .label = "polyvol.tess_args"});
        mScanProgram = gl::Program::compile({.stages = {"polyvol/tess_scan.comp"}, .label = "polyvol.tess_scan"});
    }
    if (!mEdgesProgram || mEdgesKey != definesKey) {
        mEdgesProgram = gl::Program::compile(
            {.stages = {"polyvol/tess_edges.comp"}, .defines = defines, .label = "polyvol.tess_edges"});
        mEdgesKey = definesKey;
    }
    const int faces = grid.faces;
    const std::uint32_t listCapacity = std::uint32_t(std::min<std::int64_t>(std::int64_t(n) * n, kMaxListEntries));
    const std::uint32_t keyCapacity =
        std::uint32_t(std::min<std::int64_t>(std::int64_t(n) * n * 6 * faces, kMaxKeys));
    if (mSize != n || mFaces != faces) {
        // The edge and level maps keep one layer per face (a cube's six are views' layers); the flag
        // hierarchy and the quad lists are scratch, reused face after face.
        mEdges = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_R16F, .size = {n, n, faces},
                                      .levels = 1, .label = "polyvol.edge_map"});
        mFlags = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R8UI, .size = {n, n, 1},
                                      .levels = top + 1, .label = "polyvol.tess_flags"});
        mFlags.setFilter(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
        mLevels = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_R8, .size = {n, n, faces},
                                       .levels = 1, .label = "polyvol.tess_levels"});
        mCounters = gl::Buffer::create({.bytes = kCounterWords * 4, .label = "polyvol.tess_counters"});
        mListA = gl::Buffer::create({.bytes = std::size_t(listCapacity) * 4, .label = "polyvol.tess_list_a"});
        mListB = gl::Buffer::create({.bytes = std::size_t(listCapacity) * 4, .label = "polyvol.tess_list_b"});
        mKeys = gl::Buffer::create({.bytes = std::size_t(keyCapacity) * 4, .label = "polyvol.tess_keys"});
        const std::size_t groups = (std::size_t(listCapacity) + kRefineGroup - 1) / kRefineGroup;
        mGroups = gl::Buffer::create({.bytes = groups * 2 * 4, .label = "polyvol.tess_groups"});
        mSize = n;
        mFaces = faces;
    }
    mLevelCount = top + 1;
    mLevels.clear(glm::vec4(0.0f));
    mCounters.clearZero();
    // Every face appends to the same key list (the counters carry over: each step's list is empty again
    // when the face's refinement ends), so one indirect draw covers the whole light.
    for (int face = 0; face < faces; ++face)
        buildFace(grid, face, measure, threshold, stopLevel, listCapacity, keyCapacity);

    const GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT;
    mArgsProgram.use();  // its capacities were set by buildFace
    mArgsProgram.set("uDraw", 1);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(barrier | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // The triangle count is small to read and is what the debugger reports.
    std::uint32_t counters[kCounterWords] = {};
    mCounters.download(0, sizeof(counters), counters);
    mTriangles = std::int64_t(std::min<std::uint32_t>(counters[2], keyCapacity / 3));
    mOverflow = counters[3] != 0;
}

void AdaptiveTessellation::buildFace(const VolumeGrid& grid, int face, EdgeMeasure measure, double threshold,
                                     int stopLevel, std::uint32_t listCapacity, std::uint32_t keyCapacity) {
    const int n = grid.mapSize;
    const int coarse = refinementLevels(n);
    // The stop as the refine pass takes it: quads of this level and below are leaves (-1: none is).
    const int stopAt = stopLevel < 0 ? -1 : std::max(-1, coarse - stopLevel);

    // 1. Edge map.
    mEdgesProgram.use();
    setGridUniforms(mEdgesProgram, grid);
    mEdgesProgram.set("uFace", face);
    mEdgesProgram.set("uRange", std::max(grid.range, 1e-20f));
    mEdgesProgram.set("uMeasure", int(measure));
    mEdges.bindImage(0, GL_WRITE_ONLY, 0, face);
    glDispatchCompute(GLuint((n + 7) / 8), GLuint((n + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // 2. Flags, finest level up to the coarse grid's level.
    mLevelsProgram.use();
    mLevelsProgram.set("uMapSize", n);
    mLevelsProgram.set("uThreshold", float(threshold));
    mLevelsProgram.set("uFace", face);
    mEdges.bindUnit(kUnitEdges);
    mFlags.bindUnit(kUnitFlags);
    for (int k = 0; k <= coarse; ++k) {
        mLevelsProgram.set("uLevel", k);
        mFlags.bindImage(0, GL_WRITE_ONLY, k);
        const int quads = n >> k;
        glDispatchCompute(GLuint((quads + 7) / 8), GLuint((quads + 7) / 8), 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    // 3. Refinement from the coarse grid down to level 0.
    mCounters.bindBase(GL_SHADER_STORAGE_BUFFER, kBindingCounters);
    mKeys.bindBase(GL_SHADER_STORAGE_BUFFER, kBindingKeys);
    mLevels.bindImage(1, GL_WRITE_ONLY, 0, face);
    mArgsProgram.set("uListCapacity", listCapacity);
    mArgsProgram.set("uKeyCapacity", keyCapacity);
    mRefineProgram.set("uMapSize", n);
    mRefineProgram.set("uStopLevel", stopAt);
    mRefineProgram.set("uListCapacity", listCapacity);
    mRefineProgram.set("uKeyCapacity", keyCapacity);
    mRefineProgram.set("uWriteLevels", 1);
    mRefineProgram.set("uKeyBase", std::uint32_t(face) * std::uint32_t(n + 1) * std::uint32_t(n + 1));
    mGroups.bindBase(GL_SHADER_STORAGE_BUFFER, kBindingGroups);
    const gl::Buffer* in = &mListA;
    const gl::Buffer* out = &mListB;
    const GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT;
    for (int k = coarse; k >= 0; --k) {
        const int quads = n >> k;
        mRefineProgram.set("uLevel", k);
        mRefineProgram.set("uFromGrid", k == coarse ? 1 : 0);
        in->bindBase(GL_SHADER_STORAGE_BUFFER, kBindingIn);
        out->bindBase(GL_SHADER_STORAGE_BUFFER, kBindingOut);
        mCounters.bind(GL_DISPATCH_INDIRECT_BUFFER);
        // The same quads twice: their groups' totals, then (offsets scanned in between) the lists.
        for (int pass = 0; pass < 2; ++pass) {
            mRefineProgram.use();
            mRefineProgram.set("uPass", pass);
            if (k == coarse) glDispatchCompute(GLuint((quads * quads + 63) / 64), 1, 1);
            else glDispatchComputeIndirect(GLintptr(kDispatchOffset));
            glMemoryBarrier(barrier);
            if (pass == 1) break;
            mScanProgram.use();
            mScanProgram.set("uFromGrid", k == coarse ? 1 : 0);
            mScanProgram.set("uGridQuads", std::uint32_t(quads) * std::uint32_t(quads));
            glDispatchCompute(1, 1, 1);
            glMemoryBarrier(barrier);
        }
        mArgsProgram.use();
        mArgsProgram.set("uDraw", 0);
        glDispatchCompute(1, 1, 1);
        glMemoryBarrier(barrier);
        std::swap(in, out);
    }
}

}  // namespace viz::polyvol
