#include "ray_inspection.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "pane_image.h"
#include "techniques/slices/ray_planes.h"

namespace airlight {

namespace {

// Width and height of an intermediate: its CPU image, its GL 2D texture's level 0, else its extent.
glm::ivec2 sizeOf(const viz::Intermediate& in) {
    if (in.image) return {in.image->width, in.image->height};
    if (in.glTexture != 0 && (in.glTarget == 0 || in.glTarget == GL_TEXTURE_2D)) {
        GLint w = 0, h = 0;
        glGetTextureLevelParameteriv(in.glTexture, 0, GL_TEXTURE_WIDTH, &w);
        glGetTextureLevelParameteriv(in.glTexture, 0, GL_TEXTURE_HEIGHT, &h);
        return {w, h};
    }
    return {in.extent.x, in.extent.y};
}

}  // namespace

std::vector<PixelReading> readingsAtPixel(const viz::FrameOutput& out, glm::ivec2 frame, glm::ivec2 pixel) {
    std::vector<PixelReading> readings;
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= frame.x || pixel.y >= frame.y) return readings;
    for (const viz::Intermediate& in : out.intermediates) {
        if (in.orbit) continue;  // frame-sized, but seen from another camera
        PixelReading r{in.id, in.label, in.units, 0, glm::vec4(0.0f)};
        if (in.image) {
            const viz::Image& image = *in.image;
            if (image.width != frame.x || image.height != frame.y) continue;
            r.channels = std::min(image.channels, 4);
            for (int c = 0; c < r.channels; ++c) r.value[c] = image.at(pixel.x, pixel.y, c);
        } else if (in.glTexture != 0 && (in.glTarget == 0 || in.glTarget == GL_TEXTURE_2D)) {
            GLint format = 0;
            glGetTextureLevelParameteriv(in.glTexture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
            r.channels = channelsOfFormat(format);
            if (sizeOf(in) != frame || r.channels == 0) continue;
            const int glRow = frame.y - 1 - pixel.y;
            glGetTextureSubImage(in.glTexture, 0, pixel.x, glRow, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof r.value,
                                 &r.value);
        } else {
            continue;
        }
        // Only the channels that mean something: a colour's three (an RGBA texture's alpha is padding), or
        // as many as the intermediate declares.
        if (!in.channels.empty()) r.channels = std::min(r.channels, int(in.channels.size()));
        else if (in.kind == viz::ViewKind::Colour) r.channels = std::min(r.channels, 3);
        readings.push_back(std::move(r));
    }
    return readings;
}

bool pickPixel(const viz::Technique& technique, viz::Settings& settings, glm::ivec2 pixel) {
    if (!technique.controls().pickedPixel) return false;
    const double x = double(pixel.x), y = double(pixel.y);
    const bool changed = settings[viz::kPickX] != x || settings[viz::kPickY] != y;
    settings[viz::kPickX] = x;
    settings[viz::kPickY] = y;
    return changed;
}

std::vector<std::string> pickedRayViews(const viz::Technique& technique, const viz::FrameOutput& out) {
    std::vector<std::string> ids;
    if (!technique.controls().pickedPixel) return ids;
    for (const viz::Intermediate& in : out.intermediates)
        if (in.rayView) ids.push_back(in.id);
    return ids;
}

std::vector<viz::plot::Series> rayViewSeries(const viz::FrameOutput& out) {
    const auto in = std::find_if(out.intermediates.begin(), out.intermediates.end(),
                                 [](const viz::Intermediate& i) { return i.id == "slices.ray_planes"; });
    using namespace viz::slices;
    if (in == out.intermediates.end() || !in->image || in->image->channels < 4 ||
        in->image->width < kRayPlaneColumns)
        return {};
    const viz::Image& table = *in->image;
    viz::plot::Series shaded{"slices, shaded", viz::plot::categoricalColour(5), {}, false, true};
    viz::plot::Series kept{"slices, stored", viz::plot::categoricalColour(6), {}, false, true};
    for (int row = 0; row < table.height; ++row) {
        const float t = table.at(kColWhere, row, 2), dt = table.at(kColWhere, row, 3);
        if (PickStatus(int(table.at(kColTest, row, 0))) != PickStatus::Added || !(dt > 0.0f)) continue;
        // Column kColSet: (light, set, L_air as stored, L_air as shaded), sums of rgb.
        shaded.points.push_back({double(t), double(table.at(kColSet, row, 3)) / double(dt)});
        kept.points.push_back({double(t), double(table.at(kColSet, row, 2)) / double(dt)});
    }
    if (shaded.points.empty()) return {};
    return {std::move(shaded), std::move(kept)};
}

PixelInspection inspectRun(const viz::Technique& technique, const viz::FrameOutput& out, glm::ivec2 frame,
                           glm::ivec2 pixel) {
    return {readingsAtPixel(out, frame, pixel), pickedRayViews(technique, out), rayViewSeries(out)};
}

}  // namespace airlight
