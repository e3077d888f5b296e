#include "ray_inspection.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "pane_image.h"

namespace airlight {

namespace {

bool hasParam(const viz::Technique& technique, const std::string& name) {
    return std::any_of(technique.params().begin(), technique.params().end(),
                       [&](const viz::ParamInfo& p) { return p.name == name; });
}

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
        readings.push_back(std::move(r));
    }
    return readings;
}

bool pickPixel(const viz::Technique& technique, viz::Settings& settings, glm::ivec2 pixel) {
    if (!hasParam(technique, "pick_x") || !hasParam(technique, "pick_y")) return false;
    const double x = double(pixel.x), y = double(pixel.y);
    const bool changed = settings["pick_x"] != x || settings["pick_y"] != y;
    settings["pick_x"] = x;
    settings["pick_y"] = y;
    return changed;
}

std::vector<std::string> pickedRayViews(const viz::Technique& technique, const viz::FrameOutput& out,
                                        glm::ivec2 frame) {
    std::vector<std::string> ids;
    for (const viz::StageInfo& st : technique.stages()) {
        if (std::find(st.params.begin(), st.params.end(), "pick_x") == st.params.end()) continue;
        for (const std::string& id : st.intermediates) {
            const auto in = std::find_if(out.intermediates.begin(), out.intermediates.end(),
                                         [&](const viz::Intermediate& i) { return i.id == id; });
            if (in == out.intermediates.end()) continue;  // not produced by this run
            if (sizeOf(*in) != frame) ids.push_back(id);  // per-pixel images are in the readings instead
        }
    }
    return ids;
}

PixelInspection inspectRun(const viz::Technique& technique, const viz::FrameOutput& out, glm::ivec2 frame,
                           glm::ivec2 pixel) {
    return {readingsAtPixel(out, frame, pixel), pickedRayViews(technique, out, frame)};
}

}  // namespace airlight
