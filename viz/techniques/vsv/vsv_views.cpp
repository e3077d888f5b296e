// What vsv shows beside its textures: the picked pixel's voxel column before and after the scan, and the
// markers of a picked pixel.
#include "techniques/vsv/vsv_technique.h"

namespace viz::vsv_detail {

std::vector<ViewMarker> VsvTechnique::markersFor(glm::ivec2 pixel, const std::string& id) const {
    if (render::shadowMapIndexOf(id, "vsv") >= 0) return mView.shadowMapMarkers(pixel, id, "vsv");
    if (!mMark || (id != kOccluder && id != kVoxelSlice && id != kScanSlice)) return {};
    const MarkState& m = *mMark;
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= m.size.x || pixel.y >= m.size.y) return {};
    const glm::dvec3 ray = scene::pixelRay(m.camera, m.size.x, m.size.y, pixel.x, pixel.y);
    const int theta = int(std::floor(vsv::thetaCoord(m.grid, vsv::thetaOf(m.frame, ray))));
    if (theta < 0 || theta >= m.grid.nTheta) return {};  // outside the grid (near the epipole)
    if (id == kOccluder) {
        const float v = (float(theta) + 0.5f) / float(m.grid.nTheta);
        return {{{0.0f, v}, {1.0f, v}, "theta cell " + std::to_string(theta)}};
    }
    if (theta != m.pickTheta) return {};
    const double alpha = vsv::alphaCoord(m.grid, vsv::alphaOf(m.frame, ray));
    if (alpha < 0.0 || alpha >= double(m.grid.nAlpha)) return {};
    const float u = float(alpha) / float(m.grid.nAlpha);
    return {{{u, 0.0f}, {u, 1.0f}, "eye ray, alpha cell " + std::to_string(int(alpha))}};
}

glm::ivec2 VsvTechnique::pickedCell(const scene::Scene& scene, const FrameInput& input, int sceneLight,
                             const vsv::EpipolarGrid& g, int x, int y) {
    const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(sceneLight)]);
    const glm::dvec3 ray = scene::pixelRay(scene.camera, input.width, input.height, x, y);
    return {std::clamp(int(std::floor(vsv::alphaCoord(g, vsv::alphaOf(f, ray)))), 0, g.nAlpha - 1),
            std::clamp(int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, ray)))), 0, g.nTheta - 1)};
}

std::shared_ptr<Image> VsvTechnique::columnImage(const scene::Scene& scene, const FrameInput& input, int sceneLight,
                                   const vsv::EpipolarGrid& g, int slot, int x, int y) const {
    const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(sceneLight)]);
    const glm::ivec2 cell = pickedCell(scene, input, sceneLight, g, x, y);
    const double alpha = vsv::alphaOf(f, scene::pixelRay(scene.camera, input.width, input.height, x, y));
    float d = 0.0f;
    glGetTextureSubImage(mView.surface().distance().id(), 0, x, input.height - 1 - y, 0, 1, 1, 1, GL_RED,
                         GL_FLOAT, sizeof(float), &d);
    const double kEnd = vsv::phiCoord(g, vsv::phiOnEyeRay(f, alpha, double(d)));
    const std::vector<vsv::Bits128> after = vsv::readGridRow(*mResult[std::size_t(slot)], cell.x, 1, cell.y);
    auto image = std::make_shared<Image>(g.nPhi, 2, 1);
    for (int row = 0; row < 2; ++row) {
        const std::vector<vsv::Bits128>& bits = row == 0 ? mPreScanColumn : after;
        for (int k = 0; k < g.nPhi; ++k) {
            const std::size_t at = std::size_t(k >> 7);  // one texel per 128 bits, layer by layer
            const bool set = at < bits.size() && vsv::testBitPlain(bits[at], k & 127);
            image->at(k, row) = double(k) >= kEnd ? 0.5f : (set ? 1.0f : 0.0f);
        }
    }
    return image;
}

}  // namespace viz::vsv_detail
