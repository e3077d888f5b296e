// One image shown in a window pane: a 2D float texture plus how to map it to the screen (exposure,
// range, colour map by the intermediate's kind), made from a technique's CPU image or GL texture.
#pragma once

#include <string>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "core/image.h"
#include "debug/technique.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "ui/image_view.h"
#include "ui/text_renderer.h"

namespace airlight {

// Mirrors the modes of shaders/ui/image.frag.
enum class DisplayMode : int { HdrColor = 0, RangeColor = 1, Grey = 2, Signed = 3, FalseColor = 4, Bits = 5, Mask = 6 };

DisplayMode displayModeFor(viz::ViewKind kind);

// What a pane shows: a 2D float texture plus how to map it, or the reason nothing can be shown.
struct PaneImage {
    std::string id, label, note, units;
    viz::ViewKind kind = viz::ViewKind::Color;
    DisplayMode mode = DisplayMode::HdrColor;
    float rangeMin = 0.0f, rangeMax = 1.0f;
    GLuint texture = 0;   // borrowed (technique's) or `owned`
    viz::gl::Texture owned;
    bool flipY = false;   // true for textures rendered by GL (row 0 at the bottom)
    int channels = 4;
    glm::ivec2 size{0};
    int layer = 0, layers = 1;
    std::string unavailable;  // non-empty: nothing to draw, and why
};

// Uploads a CPU image (row 0 at the top) as RGBA32F; its rows stay top-first, so no flip on display.
void uploadImage(PaneImage& pane, const viz::Image& image);

// Makes a pane from one of the technique's intermediates. A 2D float texture is sampled directly;
// other textures (integer, depth, arrays, cube maps, 3D) are read back one layer at a time.
void makePane(PaneImage& pane, const viz::Intermediate& in, int layer);

// Draws PaneImages: shaders/ui/image.vert + image.frag over an empty vertex array.
class ImageDisplay {
public:
    ImageDisplay();
    void draw(const PaneImage& pane, const viz::ui::Rect& rect, glm::ivec2 framebuffer, float exposure,
              const viz::ui::ImageViewTransform& view = {}) const;

private:
    viz::gl::Program mProgram;
    viz::gl::VertexArray mVertexArray;
    viz::gl::Sampler mSampler;
};

}  // namespace airlight
