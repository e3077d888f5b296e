#include "pane_image.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include "core/error.h"
#include "gl/readback.h"

namespace airlight {

DisplayMode displayModeFor(viz::ViewKind kind) {
    switch (kind) {
        case viz::ViewKind::Colour: return DisplayMode::RangeColour;
        case viz::ViewKind::Scalar: return DisplayMode::Grey;
        case viz::ViewKind::Signed: return DisplayMode::Signed;
        case viz::ViewKind::BitField: return DisplayMode::Bits;
        case viz::ViewKind::Mask: return DisplayMode::Mask;
        case viz::ViewKind::Depth: return DisplayMode::FalseColour;
        default: return DisplayMode::Grey;
    }
}

const std::vector<std::string>& rangeModeNames() {
    static const std::vector<std::string> names = {"suggested", "min / max", "0.1 - 99.9 %", "manual"};
    return names;
}

const std::vector<std::string>& colourMapNames() {
    static const std::vector<std::string> names = {"auto (by kind)", "grey", "sequential (heat)", "ramp",
                                                   "diverging (signed)", "bits", "categorical"};
    return names;
}

Channel defaultChannel(const PaneImage& pane) { return pane.channelInfo.empty() ? Channel::Rgb : Channel::R; }

const viz::ChannelInfo* declaredChannel(const PaneImage& pane, Channel channel) {
    const int c = int(channel) - 1;
    if (channel < Channel::R || channel > Channel::A || c >= int(pane.channelInfo.size())) return nullptr;
    return &pane.channelInfo[std::size_t(c)];
}

std::vector<std::string> channelChoices(const PaneImage& pane) {
    std::vector<std::string> names = channelNames();
    if (pane.channelInfo.empty()) return names;
    static const char* kLetters[] = {"r", "g", "b", "a"};
    names[0] = "all (r g b)";
    for (int c = 0; c < 4; ++c)
        names[std::size_t(c + 1)] = c < int(pane.channelInfo.size())
                                        ? std::string(kLetters[c]) + ": " + pane.channelInfo[std::size_t(c)].name
                                        : std::string(kLetters[c]) + " (unused)";
    return names;
}

DisplayMapping resolveMapping(const PaneImage& pane, const DisplaySettings& settings, float exposure,
                              const std::optional<ValueRange>& autoRange) {
    DisplayMapping m;
    m.channel = settings.channel;
    m.logScale = settings.logScale;
    const viz::ChannelInfo* declared = declaredChannel(pane, settings.channel);
    switch (settings.colourMap) {
        case ColourMap::Auto: m.mode = declared ? displayModeFor(declared->kind) : pane.mode; break;
        case ColourMap::Grey: m.mode = DisplayMode::Grey; break;
        case ColourMap::Sequential: m.mode = DisplayMode::Heat; break;
        case ColourMap::Ramp: m.mode = DisplayMode::FalseColour; break;
        case ColourMap::Diverging: m.mode = DisplayMode::Signed; break;
        case ColourMap::Bits: m.mode = DisplayMode::Bits; break;
        case ColourMap::Categorical: m.mode = DisplayMode::Categorical; break;
    }
    m.lo = declared ? declared->rangeMin : pane.rangeMin;
    m.hi = declared ? declared->rangeMax : pane.rangeMax;
    const bool measured = settings.range == RangeMode::MinMax || settings.range == RangeMode::Percentiles;
    if (settings.range == RangeMode::Manual) {
        m.lo = settings.manualMin;
        m.hi = settings.manualMax;
    } else if ((measured || pane.rangeFromData || pane.rangeGrowsToData) && autoRange && autoRange->valid) {
        m.lo = autoRange->lo;
        m.hi = autoRange->hi;
    }
    // HDR colour has no range, only an exposure: a range (or a log scale) maps it like a data image.
    if (m.mode == DisplayMode::HdrColour && (settings.range != RangeMode::Suggested || settings.logScale)) {
        m.mode = DisplayMode::RangeColour;
        if (settings.range == RangeMode::Suggested && autoRange && autoRange->valid) m.lo = autoRange->lo, m.hi = autoRange->hi;
        m.exposure = 0.0f;
    } else {
        m.exposure = m.mode == DisplayMode::HdrColour || m.mode == DisplayMode::RangeColour ? exposure : 0.0f;
    }
    if (m.mode == DisplayMode::RangeColour && settings.range != RangeMode::Suggested) m.exposure = 0.0f;
    // Negative values are the point of a diverging map: they are not overlaid there.
    // Auto: radiance images only (a negative radiance is a bug; in data, -1 may mean "outside the cone").
    const bool radiance = pane.id == "final" || pane.id == "airlight" || pane.units == "radiance";
    const bool wanted = settings.markNegative < 0 ? radiance : settings.markNegative != 0;
    m.markNegative = wanted && m.mode != DisplayMode::Signed;
    return m;
}

void uploadImage(PaneImage& pane, const viz::Image& image) {
    if (image.empty()) {
        pane.unavailable = "(not produced by this run)";
        return;
    }
    static constexpr GLenum kFormats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    VIZ_CHECK(image.channels >= 1 && image.channels <= 4, "image channel count must be 1..4");
    pane.owned = viz::gl::Texture::create({.target = GL_TEXTURE_2D,
                                           .format = GL_RGBA32F,
                                           .size = {image.width, image.height, 1},
                                           .label = "gui.pane." + (pane.id.empty() ? std::string("final") : pane.id)});
    pane.owned.upload(kFormats[image.channels - 1], GL_FLOAT, image.pixels.data());
    pane.texture = pane.owned.id();
    pane.flipY = false;
    pane.channels = image.channels;
    pane.size = {image.width, image.height};
}

int channelsOfFormat(GLint format) {
    switch (format) {
        case GL_R8: case GL_R16: case GL_R16F: case GL_R32F: return 1;
        case GL_RG8: case GL_RG16: case GL_RG16F: case GL_RG32F: return 2;
        case GL_RGB8: case GL_RGB16F: case GL_RGB32F: case GL_R11F_G11F_B10F: case GL_SRGB8: return 3;
        case GL_RGBA8: case GL_RGBA16: case GL_RGBA16F: case GL_RGBA32F: case GL_SRGB8_ALPHA8: return 4;
        default: return 0;  // integer, depth or something unusual: read it back instead
    }
}

viz::plot::PlotSpec plotSpecOf(const viz::PlotData& data) {
    viz::plot::PlotSpec spec;
    spec.title = data.title;
    spec.xLabel = data.xLabel;
    spec.yLabel = data.yLabel;
    spec.logX = data.logX;
    spec.logY = data.logY;
    for (std::size_t i = 0; i < data.curves.size(); ++i) {
        const viz::PlotCurve& c = data.curves[i];
        spec.series.push_back({c.name, viz::plot::categoricalColour(c.colour >= 0 ? c.colour : int(i)), c.points, c.lines,
                               c.markers});
    }
    return spec;
}

void makePane(PaneImage& pane, const viz::Intermediate& in, int layer) {
    pane.id = in.id;
    pane.plots = in.plots;
    pane.label = in.label;
    pane.note = in.note;
    pane.units = in.units;
    pane.kind = in.kind;
    pane.mode = displayModeFor(in.kind);
    pane.rangeMin = in.rangeMin;
    pane.rangeMax = in.rangeMax;
    pane.sentinels = in.sentinels;
    pane.channelInfo = in.channels;
    pane.picture = in.picture;
    pane.rangeFromData = in.rangeFromData;
    pane.rangeGrowsToData = in.rangeGrowsToData;
    if (in.image) {
        uploadImage(pane, *in.image);
        return;
    }
    if (in.glTexture == 0) {
        pane.unavailable = std::string("(a ") + viz::viewKindName(in.kind) +
                           " on the GPU, with no image of its own: the note above says which view draws it)";
        return;
    }
    const GLenum target = in.glTarget ? in.glTarget : GL_TEXTURE_2D;
    pane.layers = target == GL_TEXTURE_CUBE_MAP ? 6 : (target == GL_TEXTURE_2D ? 1 : std::max(1, in.extent.z));
    pane.layer = std::clamp(layer, 0, pane.layers - 1);
    GLint format = 0;
    if (target == GL_TEXTURE_2D) {
        glGetTextureLevelParameteriv(in.glTexture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    }
    const int channels = channelsOfFormat(format);
    if (target == GL_TEXTURE_2D && channels > 0) {
        pane.texture = in.glTexture;
        pane.flipY = true;
        pane.glRows = true;
        pane.channels = channels;
        GLint w = 0, h = 0;
        glGetTextureLevelParameteriv(in.glTexture, 0, GL_TEXTURE_WIDTH, &w);
        glGetTextureLevelParameteriv(in.glTexture, 0, GL_TEXTURE_HEIGHT, &h);
        pane.size = {w, h};
        return;
    }
    pane.glRows = true;
    try {
        uploadImage(pane, viz::gl::readTexture(in.glTexture, 0, pane.layer));
    } catch (const std::exception& e) {
        pane.unavailable = std::string("(cannot read back: ") + e.what() + ")";
    }
}

ImageDisplay::ImageDisplay() {
    mProgram = viz::gl::Program::compile({.stages = {"ui/image.vert", "ui/image.frag"}, .label = "ui.image"});
    mVertexArray = viz::gl::VertexArray::create("ui.image_vao");
    // Nearest, and no depth comparison, whatever the technique set on its own texture.
    mSampler = viz::gl::Sampler::create({.minFilter = GL_NEAREST, .magFilter = GL_NEAREST, .label = "ui.image"});
}

void ImageDisplay::draw(const PaneImage& pane, const viz::ui::Rect& rect, glm::ivec2 framebuffer,
                        const DisplayMapping& mapping, const viz::ui::ImageViewTransform& view) const {
    if (pane.texture == 0) return;
    mProgram.set("uView", glm::vec4(glm::vec2(view.center), float(view.zoom), 0.0f));
    // The texel grid only where the user zoomed in (a fitted low-resolution image stays clean).
    mProgram.set("uTexelPixels", view.zoom > 1.0 ? float(view.texelPixels(rect.size().x, std::max(1, pane.size.x))) : 0.0f);
    mProgram.set("uRect", glm::vec4(rect.min, rect.max));
    mProgram.set("uViewport", glm::vec2(framebuffer));
    mProgram.set("uMode", static_cast<int>(mapping.mode));
    glm::vec2 range(mapping.lo, mapping.hi);
    if (mapping.logScale && mapping.mode != DisplayMode::Signed) {  // the diverging map takes its own log
        const ValueRange r = logSafeRange(mapping.lo, mapping.hi);
        range = {std::log10(r.lo), std::log10(r.hi)};
    }
    mProgram.set("uRange", range);
    mProgram.set("uLog", mapping.logScale);
    mProgram.set("uChannel", static_cast<int>(mapping.channel));
    mProgram.set("uMarkNegative", mapping.markNegative);
    mProgram.set("uExposure", mapping.exposure);
    mProgram.set("uFlipY", pane.flipY);
    mProgram.set("uChannels", pane.channels);
    glm::vec4 sentinels(0.0f);
    const int count = std::min(int(pane.sentinels.size()), 4);
    for (int k = 0; k < count; ++k) sentinels[k] = pane.sentinels[std::size_t(k)].value;
    mProgram.set("uSentinels", sentinels);
    mProgram.set("uSentinelCount", count);
    mProgram.use();
    glBindTextureUnit(0, pane.texture);
    mSampler.bindUnit(0);
    mVertexArray.bind();
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindSampler(0, 0);
}

}  // namespace airlight
