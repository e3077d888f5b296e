// What slices shows beside its textures: the drawn planes as polygons, the fragments they shaded and the
// markers of a picked pixel.
#include "techniques/slices/slices_technique.h"

namespace viz::slices_detail {

std::vector<ViewMarker> SlicesTechnique::markersFor(glm::ivec2 pixel, const std::string& id) const {
    return mView.shadowMapMarkers(pixel, id, "slices");
}

Intermediate SlicesTechnique::polygonIntermediate() const {
    std::size_t width = 1;
    for (const auto& p : mPolygons) width = std::max(width, p.size());
    auto img = std::make_shared<Image>(int(width), int(std::max<std::size_t>(mPolygons.size(), 1)), 3);
    std::fill(img->pixels.begin(), img->pixels.end(), std::nanf(""));
    for (std::size_t row = 0; row < mPolygons.size(); ++row)
        for (std::size_t v = 0; v < mPolygons[row].size(); ++v)
            for (int c = 0; c < 3; ++c) img->at(int(v), int(row), c) = float(mPolygons[row][v][c]);
    Intermediate i;
    i.id = kPlaneMesh, i.label = "Sampling planes (mesh)";
    i.note = "the drawn planes clipped to the light frustum (when clip=1): rows planes, columns vertices, "
             "xyz eye-relative world";
    i.units = "scene units";
    i.kind = ViewKind::Mesh;
    i.image = img;
    i.extent = {img->width, img->height, 1};
    return i;
}

void SlicesTechnique::countFragments(const gl::Program& program, int drawn) {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    for (int pass = 1; pass <= 2; ++pass) {
        program.set("uCountPass", pass);
        mCountQuery.begin();
        glDrawArrays(GL_TRIANGLES, 0, 6 * drawn);
        mCountQuery.end();
        mQueryCounts[pass == 1 ? 1 : 0] += double(mCountQuery.count());
    }
    program.set("uCountPass", 0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

std::string SlicesTechnique::planeFragmentsNote() {
    if (mPlaneQueriesUsed == 0) return "";
    std::uint64_t fragments = 0;
    for (int i = 0; i < mPlaneQueriesUsed; ++i) fragments += mPlaneQueries[std::size_t(i)].count();
    // First in the note: a title too narrow for the whole note keeps its start.
    if (fragments == 0) return "0 fragments, black (beyond the first surface or outside the light's volume): ";
    return std::to_string(fragments) + " fragments: ";
}

Intermediate SlicesTechnique::planeIntermediate(int drawn, bool wasDrawn) {
    const std::string label = "Plane " + std::to_string(drawn);
    if (wasDrawn) {
        Intermediate i = render::textureIntermediate(kPlane, label,
                                                     planeFragmentsNote() + "the last plane drawn alone (every light), float",
                                                     "stored value", ViewKind::Colour, 0.0f, 0.05f, mPlane);
        // One plane adds from 1e-5 (a far plane in thin air) to 1e-1 (a plane through a spot's cone) of the
        // sum: a fixed range leaves most planes black.
        i.rangeFromData = true;
        return i;
    }
    // Drawing it costs one more plane per light and a wait for its fragment count: only for a caller that
    // shows it (StageInfo::onDemand), so a report's timing does not include it.
    Intermediate i;
    i.id = kPlane;
    i.label = label;
    i.note = "the last plane drawn alone (every light): drawn when this view is shown";
    i.units = "stored value";
    i.kind = ViewKind::Colour;
    return i;
}

}  // namespace viz::slices_detail
