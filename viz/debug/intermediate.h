// What a technique shows of a run: its intermediates (images, plots, their sentinels and channels) and
// the marks it draws in them for a picked pixel.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"

namespace viz {

// How an intermediate is best shown.
enum class ViewKind { Colour, Scalar, Signed, BitField, Mask, Depth, Mesh, Buffer };
const char* viewKindName(ViewKind kind);

// A plot a technique publishes with an intermediate (singular values, basis functions, per-plane values
// along a ray, ...): the window draws it with axes, ticks and a legend (viz/plot) in place of the
// intermediate's image, which stays what `airlight render --layer` writes.
struct PlotCurve {
    std::string name;                // legend entry
    std::vector<glm::dvec2> points;  // data units, drawn in order
    bool lines = true, markers = false;
    int colour = -1;                 // index into the categorical palette; -1: the curve's own index
};
struct PlotData {
    std::string title, xLabel, yLabel;
    bool logX = false, logY = false;
    std::vector<PlotCurve> curves;
};

// A value an intermediate stores to mean "nothing here" rather than a measurement (minmax's -1 outside
// the spot's cone, vsv's -1 for "no occluder", 0 for a hole in an ISM): the window shows it in the
// sentinel hatch with its meaning in the colour bar's legend, and leaves it out of the value range, the
// histogram and the NaN / Inf / negative counts. It applies to every channel of the intermediate.
struct Sentinel {
    float value = 0.0f;
    std::string meaning;  // "outside the spot's cone"
};

// One quantity of an intermediate that packs several into its channels (polyvol's crossings: faces
// crossed, signed count, clamped faces): the window shows one channel at a time, picked by name, with
// its own units, range and colour map.
struct ChannelInfo {
    std::string name;   // "faces crossed"
    std::string units;  // "count"
    ViewKind kind = ViewKind::Scalar;
    float rangeMin = 0.0f, rangeMax = 1.0f;
};

// A published intermediate: either a CPU image or a GL texture owned by the technique (valid until the
// next run()). Meshes and buffers carry a GL name and a short description of their layout.
struct Intermediate {
    std::string id;       // "raymarch.shadow_map"
    std::string label;    // "Shadow map"
    std::string note;     // one-line explanation
    std::string units;    // "scene units", "W/(m^2 sr)", ...
    ViewKind kind = ViewKind::Scalar;
    float rangeMin = 0.0f, rangeMax = 1.0f;  // suggested display range
    std::shared_ptr<const Image> image;      // CPU storage, or
    unsigned glTexture = 0;                  // GL texture name (GL_TEXTURE_2D, or a cube map/array: layers)
    unsigned glTarget = 0;
    glm::ivec3 extent{0};
    // An orbit view (render::MeshView): the window turns it by dragging (the technique's mesh_yaw and
    // mesh_pitch parameters).
    bool orbit = false;
    // Plots of the same data, stacked top to bottom in the window's view (empty: the image is shown).
    std::vector<PlotData> plots{};
    // Shows the picked pixel's ray (the technique's pick_x / pick_y): a walk, a voxel column, per-VPL
    // terms, the planes along it. The ray inspector lists these by id.
    bool rayView = false;
    std::vector<Sentinel> sentinels{};
    // A picture the technique draws (a chart, an orbit view, a schematic): its colours are explained in
    // its note, not by a colour map, and the window's colour bar says so.
    bool picture = false;
    // The suggested range is the data's own: the window measures it from the 2nd and 98th percentiles
    // (a diverging map takes the larger magnitude of the two), so that a peak does not wash out the rest
    // (polyvol's signed total, whose values run from 1e-3 to its light's peak).
    bool rangeFromData = false;
    // The suggested range is the declared one (of the channel shown), widened to hold the data's 1st to
    // 99th percentile: counts that mostly fit the declared range but can exceed it (polyvol's
    // crossings, where many light volumes overlap: tv-room's VPL cubes cross every eye ray). A diverging
    // channel widens symmetrically about 0.
    bool rangeGrowsToData = false;
    // Empty: the channels are one quantity (a colour, or a scalar in r). Else channel i (r, g, b, a) is
    // channels[i]; the window starts on the first.
    std::vector<ChannelInfo> channels{};
};

// A mark a technique can draw in one of its algorithm-space intermediates for a screen pixel (the
// window's linked cursors: the epipolar row of the pixel in a rectified map, say). A segment from
// `from` to `to` (equal: a point) in the intermediate's data uv: [0,1]^2 over its columns and its rows
// as stored (row 0 = the first row; a GL texture, and each layer of a GL array or cube map, shows it at
// the bottom).
struct ViewMarker {
    glm::vec2 from{0.0f}, to{0.0f};
    std::string label;  // short, e.g. "slice 37"
    // The layer (array layer, cube face 0..5 = +X -X +Y -Y +Z -Z) the mark belongs to; -1: every layer.
    int layer = -1;
};

// An intermediate the technique computed on the CPU: `image`, its extent, a suggested range [lo, hi].
inline Intermediate cpuIntermediate(const std::string& id, const std::string& label, const std::string& note,
                                    ViewKind kind, std::shared_ptr<const Image> image, float lo = 0.0f,
                                    float hi = 1.0f) {
    Intermediate i;
    i.id = id;
    i.label = label;
    i.note = note;
    i.kind = kind;
    i.rangeMin = lo;
    i.rangeMax = hi;
    i.extent = glm::ivec3(image->width, image->height, 1);
    i.image = std::move(image);
    return i;
}

}  // namespace viz
