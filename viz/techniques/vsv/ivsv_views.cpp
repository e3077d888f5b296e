// What ivsv shows beside its textures: VPL positions, the point cloud, the picked pixel's voxel column,
// per-VPL visibility, the interleave pattern and the markers of a picked pixel.
#include "techniques/vsv/ivsv_technique.h"

namespace viz::ivsv_detail {

std::vector<ViewMarker> IvsvTechnique::markersFor(glm::ivec2 pixel, const std::string& id) const {
    if (!mSurfaceRan) return {};
    if (render::shadowMapIndexOf(id, "ivsv") >= 0) return mView.shadowMapMarkers(pixel, id, "ivsv");
    const int naive = render::shadowMapIndexOf(id, "ivsv.naive");
    if (naive >= 0) {
        // mode=naive: VPL i as point light i; the same eye, so the same eye-relative space.
        const auto& lights = mNaiveView.lights().lights();
        glm::dvec3 w;
        double tEnd = 0.0;
        if (!mNaiveBuilt || naive >= int(lights.size()) || lights[std::size_t(naive)].info.z < 0 ||
            !mView.pixelRay(pixel, w, tEnd))
            return {};
        return render::shadowMapMarkers(mNaiveView.shadows(), lights[std::size_t(naive)], w, tEnd);
    }
    if (!mMark) return {};
    const MarkState& m = *mMark;
    glm::dvec3 w;
    double d = 0.0;
    if (!mView.pixelRay(pixel, w, d)) return {};
    const vsv::Vpl& vpl = mVpls[std::size_t(m.shown)];
    if (id == kVoxelSlice || id == kScanSlice) {
        // As vsv: the slices show theta cell pickTheta of the shown VPL's grid (alpha x, phi y); the eye
        // ray is the column at its alpha when its theta cell is that one.
        const vsv::EpipolarFrame f = vsv::makeFrame(vpl.position - m.eye);
        const vsv::EpipolarGrid& g = mGrids[std::size_t(m.shown)];
        const int theta = int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, w))));
        if (theta != m.pickTheta) return {};
        const double alpha = vsv::alphaCoord(g, vsv::alphaOf(f, w));
        if (alpha < 0.0 || alpha >= double(g.nAlpha)) return {};
        const float u = float(alpha) / float(g.nAlpha);
        return {{{u, 0.0f}, {u, 1.0f}, "eye ray, alpha cell " + std::to_string(int(alpha))}};
    }
    if ((id == kIsm || id == kIsmRaw) && !m.naive) return ismMarkers(m, vpl, w, d);
    return {};
}

std::vector<ViewMarker> IvsvTechnique::ismMarkers(const MarkState& m, const vsv::Vpl& vpl, const glm::dvec3& w, double d) const {
    glm::dvec3 tx, ty;
    vsv::hemisphereFrame(vpl.normal, tx, ty);
    const glm::dvec3 from = vpl.position - m.eye;  // eye-relative
    const glm::dvec2 origin(tileOrigin(m.shown, m.tile));
    const glm::dvec2 atlas(double(mTilesX * m.tile), double(mTilesY * m.tile));
    const auto project = [&](double t, glm::vec2& uv) {
        const glm::dvec3 v = t * w - from;
        const double len = glm::length(v);
        if (len <= 0.0) return false;
        const glm::dvec3 local(glm::dot(v, tx) / len, glm::dot(v, ty) / len, glm::dot(v, vpl.normal) / len);
        if (local.z <= 0.0) return false;
        const glm::dvec2 texel = origin + (vsv::paraboloid(local) * 0.5 + 0.5) * double(m.tile);
        uv = glm::vec2(texel / atlas);
        return true;
    };
    constexpr int kPieces = 48;
    std::vector<ViewMarker> marks;
    glm::vec2 previous(0.0f);
    bool previousIn = project(0.0, previous);
    for (int k = 1; k <= kPieces; ++k) {
        glm::vec2 uv(0.0f);
        const bool in = project(d * double(k) / kPieces, uv);
        if (in && previousIn) {
            char text[96];
            text[0] = 0;
            if (marks.empty()) std::snprintf(text, sizeof text, "eye ray t=0..%.2f, VPL %d", d, m.shown);
            marks.push_back({previous, uv, text});
        }
        previous = uv;
        previousIn = in;
    }
    return marks;
}

std::shared_ptr<Image> IvsvTechnique::vplImage() const {
    constexpr int kSize = 64;
    auto image = std::make_shared<Image>(kSize, kSize, 3);
    double peak = 0.0;
    for (const vsv::Vpl& v : mVpls) peak = std::max(peak, std::max(v.weight.x, std::max(v.weight.y, v.weight.z)));
    for (const vsv::Vpl& v : mVpls) {
        const auto colour = [&](int c) { return float(peak > 0.0 ? v.weight[c] / peak : 1.0); };
        // A grid VPL's cell at 60 % of its colour, its last row and column left dark as the cells' edges.
        const glm::dvec2 lo = v.uv - 0.5 * v.uvSize, hi = v.uv + 0.5 * v.uvSize;
        for (int y = int(std::lround(lo.y * kSize)); y < int(std::lround(hi.y * kSize)) - 1; ++y)
            for (int x = int(std::lround(lo.x * kSize)); x < int(std::lround(hi.x * kSize)) - 1; ++x)
                if (x >= 0 && y >= 0 && x < kSize && y < kSize)
                    for (int c = 0; c < 3; ++c) image->at(x, y, c) = 0.6f * colour(c);
        const int x = std::clamp(int(v.uv.x * kSize), 0, kSize - 1);
        const int y = std::clamp(int(v.uv.y * kSize), 0, kSize - 1);
        for (int c = 0; c < 3; ++c) image->at(x, y, c) = colour(c);
    }
    return image;
}

std::shared_ptr<Image> IvsvTechnique::pointCloudImage(const scene::Scene& scene, int width, int height, int vpl, int count) const {
    auto image = std::make_shared<Image>(width, height, 1);
    const scene::Camera& cam = scene.camera;
    const glm::dvec3 right = scene::cameraRight(cam);
    const double tanY = std::tan(cam.yfov * 0.5), tanX = tanY * scene::aspectOf(cam, width, height);
    for (std::size_t i = std::size_t(vpl); i < mCloudWorld.size(); i += std::size_t(count)) {
        const glm::dvec3 p = mCloudWorld[i] - cam.position;
        const double z = glm::dot(p, cam.forward);
        if (z <= cam.znear) continue;
        const double nx = glm::dot(p, right) / (z * tanX), ny = glm::dot(p, cam.up) / (z * tanY);
        const int x = int(std::floor((nx + 1.0) * 0.5 * width)), y = int(std::floor((1.0 - ny) * 0.5 * height));
        if (x < 0 || x >= width || y < 0 || y >= height) continue;
        const float t = float(glm::length(p));
        if (image->at(x, y) == 0.0f || t < image->at(x, y)) image->at(x, y) = t;
    }
    return image;
}

glm::ivec2 IvsvTechnique::pickedCell(const scene::Scene& scene, const FrameInput& input, int vpl, int cells, int x, int y) const {
    const vsv::EpipolarFrame f = vsv::makeFrame(mVpls[std::size_t(vpl)].position - scene.camera.position);
    const vsv::EpipolarGrid& g = mGrids[std::size_t(vpl)];
    const glm::dvec3 ray = scene::pixelRay(scene.camera, input.width, input.height, x, y);
    return {std::clamp(int(std::floor(vsv::alphaCoord(g, vsv::alphaOf(f, ray)))), 0, cells - 1),
            std::clamp(int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, ray)))), 0, cells - 1)};
}

std::shared_ptr<Image> IvsvTechnique::columnImage(const scene::Scene& scene, const FrameInput& input, int vpl, int cells, int x,
                                   int y) const {
    const vsv::EpipolarFrame f = vsv::makeFrame(mVpls[std::size_t(vpl)].position - scene.camera.position);
    const vsv::EpipolarGrid& g = mGrids[std::size_t(vpl)];
    const double alpha = vsv::alphaOf(f, scene::pixelRay(scene.camera, input.width, input.height, x, y));
    const glm::ivec2 cell = pickedCell(scene, input, vpl, cells, x, y);
    float d = 0.0f;
    glGetTextureSubImage(mView.surface().distance().id(), 0, x, input.height - 1 - y, 0, 1, 1, 1, GL_RED,
                         GL_FLOAT, sizeof(float), &d);
    const double kEnd = vsv::phiCoord(g, vsv::phiOnEyeRay(f, alpha, double(d)));
    const glm::ivec2 origin = tileOrigin(vpl, cells);
    const vsv::Bits128 after = vsv::readGridRow(*mResult, origin.x + cell.x, 1, origin.y + cell.y).front();
    auto image = std::make_shared<Image>(kPhiBits, 2, 1);
    for (int row = 0; row < 2; ++row)
        for (int k = 0; k < kPhiBits; ++k)
            image->at(k, row) = double(k) >= kEnd ? 0.5f
                                                  : (vsv::testBitPlain(row == 0 ? mPreScanColumn : after, k) ? 1.0f : 0.0f);
    return image;
}

std::shared_ptr<Image> IvsvTechnique::perVplImage(int count) const {
    const std::vector<glm::vec4> values = mPick.download<glm::vec4>();
    auto image = std::make_shared<Image>(count, 1, 3);
    for (int i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c) image->at(i, 0, c) = values[std::size_t(i)][c];
    return image;
}

PlotData IvsvTechnique::perVplPlot(const Image& perVpl) {
    PlotData p;
    p.title = "per-VPL airlight (luminance, unscaled)";
    p.xLabel = "VPL index";
    p.yLabel = "contribution";
    PlotCurve gathered{"gathered VPLs", {}, false, true, 0};
    for (int i = 0; i < perVpl.width; ++i) {
        const double y = 0.2126 * perVpl.at(i, 0, 0) + 0.7152 * perVpl.at(i, 0, 1) + 0.0722 * perVpl.at(i, 0, 2);
        if (y != 0.0 && std::isfinite(y)) gathered.points.push_back({double(i), y});
    }
    p.curves = {gathered};
    return p;
}

std::shared_ptr<Image> IvsvTechnique::interleaveImage(int width, int height, int mode, int phaseShift) {
    auto image = std::make_shared<Image>(width, height, 1);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int glY = height - 1 - y;  // the gather works in GL rows
            const int subset = ((x % 3) + 3 * (glY % 3) + phaseShift) % 9;  // as ivsv_gather.comp's phase
            image->at(x, y) = mode == kGatherInterleaved ? float(subset) / 8.0f : 0.0f;
        }
    return image;
}

Intermediate IvsvTechnique::interleaveIntermediate(int width, int height, int mode, int phaseShift) {
    std::string note = "which ninth of the VPLs each pixel gathers (subset 0..8, shown /8)";
    if (mode != kGatherInterleaved)
        note = "black: gather=" + std::string(mode == kGatherFull ? "full" : "quarter") +
               " gathers every VPL at every pixel it shades (gather=interleaved draws the 3x3 pattern here)";
    else if (phaseShift != 0)
        note += "; subsets=per-frame: shifted by " + std::to_string(phaseShift) + " on this frame";
    return cpuIntermediate(kInterleave, "Interleaving pattern", note, ViewKind::Scalar,
                           interleaveImage(width, height, mode, phaseShift));
}

}  // namespace viz::ivsv_detail
