// What minmax shows: its intermediates (the GPU's textures and the CPU-drawn charts of charts.h) and
// the markers of a picked pixel.
#include "techniques/minmax/minmax_technique.h"

namespace viz::minmax_detail {

std::vector<ViewMarker> MinmaxTechnique::markersFor(glm::ivec2 pixel, const std::string& id) const {
    if (render::shadowMapIndexOf(id, "minmax") >= 0) return mView.shadowMapMarkers(pixel, id, "minmax");
    const bool rectified = id == kRectified || id == kRectifiedView;
    if (mWork.empty() || (!rectified && id != kTree)) return {};
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= mMarkSize.x || pixel.y >= mMarkSize.y) return {};
    const auto f = minmax::toFloat(mWork.front().setup.frame);
    const glm::vec3 w = glm::vec3(scene::pixelRay(mMarkCamera, mMarkSize.x, mMarkSize.y, pixel.x, pixel.y));
    const int row = minmax::sliceRow(f, minmax::alphaOf(f, w));
    const float v = (float(row) + 0.5f) / float(std::max(1, f.slices));
    // Tree texels: leaves at columns .. 2 columns - 1 (Ahnentafel order) of a row 2 columns wide.
    const float x0 = rectified ? 0.0f : 0.5f, width = rectified ? 1.0f : 0.5f;
    const std::string label = "slice " + std::to_string(row);
    std::vector<ViewMarker> marks = {{{0.0f, v}, {1.0f, v}, label}};
    if (mMarkTraversed && mRayCoords && mRayCoords.size().x == mMarkSize.x && mRayCoords.size().y == mMarkSize.y) {
        float coords[4] = {0.0f, 0.0f, 0.0f, 0.0f}, near = 0.0f;
        const int glRow = mMarkSize.y - 1 - pixel.y;
        glGetTextureSubImage(mRayCoords.id(), 0, pixel.x, glRow, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof coords, coords);
        glGetTextureSubImage(mNearMask.id(), 0, pixel.x, glRow, 0, 1, 1, 1, GL_RED, GL_FLOAT, sizeof near, &near);
        // Near the epipole the pixel is marched by brute force: there is no walk along the row.
        if (near < 0.5f && std::isfinite(coords[2])) {
            const float end = std::clamp(coords[2] / float(std::max(1, f.columns)), 0.0f, 1.0f);
            marks.push_back({{x0, v}, {x0 + width * end, v}, "ray: columns 0.." + std::to_string(int(coords[2]))});
        }
    }
    return marks;
}

std::vector<float> MinmaxTechnique::readRow(const gl::Texture& t, int row, int channels) {
    const int width = t.size().x;
    std::vector<float> v(std::size_t(width * channels));
    glGetTextureSubImage(t.id(), 0, 0, row, 0, width, 1, 1, channels == 1 ? GL_RED : GL_RG, GL_FLOAT,
                         GLsizei(v.size() * sizeof(float)), v.data());
    return v;
}

int MinmaxTechnique::pickedRow(const FrameInput& input) const {
    const glm::ivec2 px = pickedPixel(input);
    const auto f = minmax::toFloat(mWork.front().setup.frame);
    const glm::vec3 w = glm::vec3(scene::pixelRay(input.scene->camera, input.width, input.height, px.x, px.y));
    return minmax::sliceRow(f, minmax::alphaOf(f, w));
}

void MinmaxTechnique::publishRectified(FrameOutput& out, const FrameInput& input) const {
    if (mWork.empty() || input.scene->medium.sigma_s == 0.0) return;
    const LightWork& w = mWork.front();
    out.intermediates.push_back(render::textureIntermediate(
        kRectified, "Rectified shadow map S", "rows: slices alpha; columns: light rays gamma; value: beta of the "
        "occluder (4 = unblocked, -1 = outside the cone)", "radians", ViewKind::Scalar, 0.0f,
        float(std::numbers::pi), w.rectified));
    out.intermediates.back().sentinels = outsideAndUnblocked();
    // Only the rows the picture shows (at most 1024), copied on the GPU into one texture and read back once.
    // Not one read-back per row: every glGetTextureSubImage waits for the GPU, and the 1024 rows of a
    // 1920x1080 frame took about 1.9 s per run on an NVIDIA H100 (README.md, "Measured on an NVIDIA H100"),
    // against 25 ms on llvmpipe. Not the whole map: at 1920x1080 it has up to 16384 rows of the shadow map's
    // 2048 columns, 134 MB read back and built into a 1024-row picture every frame.
    const gl::Texture& t = w.rectified;
    const int columns = t.size().x;
    const auto readRows = [&](const std::vector<int>& sources) {
        const int n = int(sources.size());
        if (!mRectifiedRows || mRectifiedRows.size() != glm::ivec3(columns, n, 1))
            mRectifiedRows = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F, .size = {columns, n, 1},
                                                  .levels = 1, .label = "minmax.rectified_view_rows"});
        for (int k = 0; k < n; ++k)
            glCopyImageSubData(t.id(), GL_TEXTURE_2D, 0, 0, sources[std::size_t(k)], 0, mRectifiedRows.id(),
                               GL_TEXTURE_2D, 0, 0, k, 0, columns, 1, 1);
        std::vector<float> rows(std::size_t(columns) * std::size_t(n));
        glGetTextureImage(mRectifiedRows.id(), 0, GL_RED, GL_FLOAT, GLsizei(rows.size() * sizeof(float)),
                          rows.data());
        return rows;
    };
    auto img = std::make_shared<Image>(minmax::rectifiedView(readRows, columns, t.size().y, pickedRow(input)));
    out.intermediates.push_back(cpuIntermediate(
        kRectifiedView, "Rectified map, picked row",
        "S / pi as grey (row 0 at the top = slice 0; nearest rows and columns when larger than 1024), the "
        "picked pixel's slice in red", ViewKind::Colour, img));
    out.intermediates.back().picture = true;
}

void MinmaxTechnique::publishLowRank(FrameOutput& out) const {
    if (mWork.empty()) return;
    const LightWork& w = mWork.front();
    const minmax::LowRank& lr = w.lowRank;
    char note[160];
    std::snprintf(note, sizeof note, "log10 bars over 12 decades, kept in green; rank-%d reconstruction error of "
                  "I sin(beta) on the 64x64 grid: %.3g", lr.rank, lr.reconstructionError);
    out.intermediates.push_back(cpuIntermediate(kSingularValues, "Singular values of I", note,
                                                          ViewKind::Colour,
                                                          std::make_shared<Image>(minmax::singularValuesView(lr))));
    out.intermediates.back().plots = {minmax::singularValuesPlot(lr)};
    out.intermediates.push_back(cpuIntermediate(
        kBasis, "B_i(beta) and Gamma_i(gamma)",
        "top: B_i over the screen's beta range; bottom: Gamma_i over [gammaLo, gammaHi]; each half scaled to its "
        "largest magnitude, zero in the middle; i = 1.. in red, green, blue, yellow, ...",
        ViewKind::Colour, std::make_shared<Image>(minmax::basisView(lr))));
    out.intermediates.back().plots = minmax::basisPlots(lr, w.setup.frame.kind == minmax::LightKind::Directional);
    // Where the factorisation errs, cell by cell, on a range of its own (the errors are small: 0 to 1 showed
    // a black square).
    auto error = std::make_shared<Image>(minmax::reconstructionErrorView(lr));
    float worst = 0.0f;
    for (float v : error->pixels) worst = std::max(worst, v);
    char errorNote[200];
    std::snprintf(errorNote, sizeof errorNote,
                  "|I - I_N| / max |I| per cell of the 64 x 64 grid of I sin(beta), first epipolar light; x: gamma, "
                  "y: beta (top: the screen's smallest); rank %d: ||I - I_N|| / ||I|| = %.3g", lr.rank,
                  lr.reconstructionError);
    out.intermediates.push_back(cpuIntermediate(kReconstructionError, "Rank-N reconstruction error", errorNote,
                                                ViewKind::Scalar, error, 0.0f, worst > 0.0f ? worst : 1.0f));
    out.intermediates.push_back(render::textureIntermediate(
        kPrefixSums, "Prefix sums of Gamma_i T", "x: gamma texel boundary k; y: slice (one row when shared); "
        "layer q / 4, channel q % 4 holds rank i = q / 3, colour q % 3", "", ViewKind::Colour, 0.0f, 1.0f,
        w.prefix));
}

void MinmaxTechnique::publishRowGamma(FrameOutput& out) const {
    const auto it = std::find_if(mWork.begin(), mWork.end(), [](const LightWork& w) { return w.point(); });
    if (it == mWork.end()) return;
    const std::vector<std::uint32_t> bits = it->rowGamma.download<std::uint32_t>();
    auto img = std::make_shared<Image>(1, int(bits.size()), 1);
    for (std::size_t i = 0; i < bits.size(); ++i) img->at(0, int(i), 0) = std::bit_cast<float>(bits[i]);
    out.intermediates.push_back(cpuIntermediate(
        kRowGamma, "Gamma range per slice (point light)",
        "row i = slice i: gamma_hi, the largest angle at the light (between light->eye and light->point) that "
        "the slice's pixels' rays reach at their distance d; the row's columns cover [0, gamma_hi] (0: no "
        "pixel in the slice)", ViewKind::Scalar, img));
}

std::vector<glm::vec2> MinmaxTechnique::readTreeRow(const gl::Texture& tree, int row) {
    const std::vector<float> raw = readRow(tree, row, 2);
    std::vector<glm::vec2> nodes(raw.size() / 2);
    for (std::size_t k = 0; k < nodes.size(); ++k) nodes[k] = {raw[2 * k], raw[2 * k + 1]};
    return nodes;
}

void MinmaxTechnique::publishTree(FrameOutput& out, const FrameInput& input) const {
    if (mWork.empty() || input.scene->medium.sigma_s == 0.0) return;
    const LightWork& w = mWork.front();
    out.intermediates.push_back(render::textureIntermediate(
        kTree, "Min-max mipmaps", "row = slice, x = Ahnentafel node (1 = root, leaves at columns..2 columns-1); "
        "r = min, g = max of S below the node", "radians", ViewKind::Colour, 0.0f, float(std::numbers::pi),
        w.tree));
    out.intermediates.back().sentinels = outsideAndUnblocked();
    out.intermediates.back().channels = {{"min S below the node", "radians", ViewKind::Scalar, 0.0f, float(std::numbers::pi)},
                                         {"max S below the node", "radians", ViewKind::Scalar, 0.0f, float(std::numbers::pi)}};
    out.intermediates.push_back(cpuIntermediate(
        kPyramid, "Min-max pyramid, picked row",
        "level 0 (root) at the top; each band: min (upper half), max (lower half) as beta / pi; blue = level "
        "not built yet (mip_levels)", ViewKind::Colour,
        std::make_shared<Image>(minmax::pyramidView(readTreeRow(w.tree, pickedRow(input)), w.levelsBuilt))));
    out.intermediates.back().picture = true;
}

void MinmaxTechnique::publishTraverse(FrameOutput& out, const FrameInput& input) {
    out.intermediates.push_back(render::textureIntermediate(
        kAirlight, "L_air", "single-scattered light reaching the eye", "radiance", ViewKind::Colour, 0.0f, 1.0f,
        mAirlight));
    // A scene without an epipolar light (area lights only) leaves these black: they say why, first (a
    // title too narrow for the whole note keeps its start).
    const std::string none = mWork.empty() ? "all 0 here: no spot, directional or point light (area lights' VPLs are "
                                             "marched by brute force, without a tree); "
                                           : "";
    const FeaturePlan* near = findFeature(out.plan, "NEAR_EPIPOLE");
    const std::string nearOff = !none.empty() ? none : near && !near->enabled ? "all 0 here: " + near->why + "; " : "";
    out.intermediates.push_back(render::textureIntermediate(
        kVisited, "Nodes visited", none + "tree nodes (or texels, traversal=linear) processed per pixel, all lights",
        "nodes", ViewKind::Scalar, 0.0f, 64.0f, mVisited));
    out.intermediates.push_back(render::textureIntermediate(
        kNearMask, "Near-epipole mask", nearOff + "1: marched by brute force near the epipole", "", ViewKind::Mask,
        0.0f, 1.0f, mNearMask));
    out.intermediates.push_back(render::textureIntermediate(
        kRayCoords, "Ray coordinates", none + "first epipolar light: (slice row, beta, end column cEnd, d) per pixel",
        "", ViewKind::Colour, 0.0f, 1.0f, mRayCoords));
    const glm::ivec3 map = mWork.empty() ? glm::ivec3(1) : mWork.front().rectified.size();  // columns x slices
    out.intermediates.back().channels = {
        {"slice row", "rows", ViewKind::Scalar, 0.0f, float(std::max(1, map.y))},
        {"beta", "radians", ViewKind::Scalar, 0.0f, float(std::numbers::pi)},
        {"end column cEnd", "columns", ViewKind::Scalar, 0.0f, float(std::max(1, map.x))},
        {"distance d", "scene units", ViewKind::Depth, 0.0f, float(input.scene->camera.zfar)}};
    if (mWork.empty() || input.scene->medium.sigma_s == 0.0) return;
    // The picked ray against its row's heightfield (Figure 4), from the GPU's own (row, beta, cEnd).
    const LightWork& w = mWork.front();
    const glm::ivec2 px = pickedPixel(input);
    float coords[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glGetTextureSubImage(mRayCoords.id(), 0, px.x, input.height - 1 - px.y, 0, 1, 1, 1, GL_RGBA, GL_FLOAT,
                         sizeof coords, coords);
    const int row = std::clamp(int(coords[0]), 0, w.setup.frame.slices - 1);
    const std::vector<glm::vec2> tree = readTreeRow(w.tree, row);
    // Stepping the walk goes as far as it has nodes (a walk of one node or none is one sub-step).
    out.substepCounts[kTraverseIndex] = std::max(1, minmax::walkLength(tree, coords[1], coords[2]));
    out.intermediates.push_back(cpuIntermediate(
        kTrace, "Picked ray vs heightfield",
        "top: S of the picked pixel's slice as a heightfield over columns (grey; a ray is lit where it passes "
        "below it: beta < S; vertical range fitted to the row and the ray), the ray's beta in yellow up to its "
        "end; below: the nodes the walk visited (CPU mirror of the shader, first trace_steps), one band per "
        "level, green lit, red shadowed, grey mixed. A pixel marched near the epipole has no walk (row 0, "
        "beta 0 shown)", ViewKind::Colour,
        std::make_shared<Image>(minmax::traceView(tree, coords[1], coords[2],
                                                  int(substepLimit(input, kTraverseIndex))))));
    out.intermediates.back().rayView = true;
    out.intermediates.back().picture = true;
}

}  // namespace viz::minmax_detail
