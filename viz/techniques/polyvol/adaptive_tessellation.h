// Adaptive tessellation of a light volume's grids (Billeter et al. 2010, section 4.1) on the GPU, one 2D
// map's grid or the six faces of a cube map's, face after face:
//   1. edge map of the vertex distances: the paper's Laplacian or our sum of absolute second differences,
//      which also refines curved receivers the Laplacian misses (saddles) (tess_edges.comp);
//   2. mip-like hierarchy of "needs subdivision" flags with the one-level balance rule (tess_levels.comp);
//   3. refinement from a coarse grid of 16 x 16 quads, one compute step per level with indirect dispatch,
//      leaves emitting one of 16 T-junction-free patterns (<= 6 triangles) (tess_refine.comp), each step
//      in two passes with a prefix sum between them (tess_scan.comp) so that the lists, and the order the
//      volume pass adds the triangles up in, are the same on every run;
//   4. an indirect draw of the emitted vertex keys (light_volume_mesh.h, key stride N + 1).
// N must be a power of two. The grid is the virtual (N + 1)^2 vertex grid whose last row and column are
// clamped onto the map's last texel (zero-area slivers), so that quads of 2^k texels tile it; the border
// ring stays at the finest level, so gridClosure(N + 1) (2D) or cubeSeams(N, N + 1) (the cube's faces, whose
// seams join border texels) closes it without T-junctions.
#pragma once

#include <cstdint>
#include <string>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "techniques/polyvol/volume_grid.h"

namespace viz::polyvol {

// Which vertices need the finest level: the paper's Laplacian, or the absolute second differences along
// x, y and both diagonals (zero only where the vertices lie on a plane).
enum class EdgeMeasure { Laplacian = 0, SecondDifferences = 1 };

class AdaptiveTessellation {
public:
    // Coarse grid: quads of 2^(log2 N - kCoarseSteps) texels (16 x 16 quads).
    static constexpr int kCoarseSteps = 4;
    // The levels the refinement descends below the coarse grid of an N^2 map: log2 N - kCoarseSteps, at
    // least 0 (N a power of two, at least 16).
    static int refinementLevels(int mapSize);

    // Builds the mesh of one light: each of grid.faces faces (1, or a cube's 6) refined on its own, their
    // triangles in one key list. The light buffer and shadow maps must be bound. threshold: the edge
    // measure relative to the map's range above which a vertex needs the finest level; stopLevel: how many
    // levels to refine below the coarse grid (stepping: 0 = the coarse grid's quads are leaves; -1, or
    // refinementLevels(N) and above, = refine fully). Counted from each grid's own coarse level, so one
    // step refines a light's 2D map and its VPLs' smaller cube maps alike.
    // defines: the light feature switches of the volume program (LIGHTS_NO_SPOT, ...), key: their id.
    void build(const VolumeGrid& grid, EdgeMeasure measure, double threshold, int stopLevel, const gl::ShaderDefines& defines,
               const std::string& definesKey);

    // The emitted keys (bind at kFirstFreeSsboBinding) and the indirect draw (GL_DRAW_INDIRECT_BUFFER at
    // drawOffset()).
    const gl::Buffer& keys() const { return mKeys; }
    const gl::Buffer& counters() const { return mCounters; }
    static std::size_t drawOffset();
    // Read back after build(): triangles emitted and whether a buffer overflowed (the mesh is then cut).
    std::int64_t triangles() const { return mTriangles; }
    bool overflowed() const { return mOverflow; }
    // One layer per face of the last light built.
    const gl::Texture& edgeMap() const { return mEdges; }
    const gl::Texture& levelMap() const { return mLevels; }
    int levels() const { return mLevelCount; }

private:
    void buildFace(const VolumeGrid& grid, int face, EdgeMeasure measure, double threshold, int stopLevel,
                   std::uint32_t listCapacity, std::uint32_t keyCapacity);

    gl::Program mEdgesProgram, mLevelsProgram, mRefineProgram, mArgsProgram, mScanProgram;
    std::string mEdgesKey;
    gl::Texture mEdges, mFlags, mLevels;
    gl::Buffer mCounters, mListA, mListB, mKeys, mGroups;
    int mSize = 0, mFaces = 0, mLevelCount = 0;
    std::int64_t mTriangles = 0;
    bool mOverflow = false;
};

}  // namespace viz::polyvol
