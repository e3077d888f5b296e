// Batched 2D drawing for the GUI shell and plots: solid rectangles, lines and text, collected on the CPU in a DrawList
// and drawn by TextRenderer with one draw call over the glyph atlas (rectangles sample its opaque
// texel). Coordinates: framebuffer pixels, origin top-left, y down. Colours are display (sRGB) values.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "ui/font.h"

namespace viz::ui {

struct Rect {
    glm::vec2 min{0.0f}, max{0.0f};
    bool contains(glm::vec2 p) const { return p.x >= min.x && p.y >= min.y && p.x < max.x && p.y < max.y; }
    glm::vec2 size() const { return max - min; }
};

// 8-bit RGBA, packed in memory order r, g, b, a (what the vertex attribute reads).
std::uint32_t packColour(glm::vec4 rgba);

struct UiVertex {
    glm::vec2 position;  // framebuffer pixels
    glm::vec2 uv;        // atlas uv
    std::uint32_t colour;
};

class DrawList {
public:
    explicit DrawList(const FontAtlas& font) : mFont(&font) {}

    void clear() {
        mVertices.clear();
        mClips.clear();
    }
    // Clipping: axis-aligned quads (rectangles, glyphs) are cut to the innermost clip rectangle with
    // their uvs; other shapes are dropped when entirely outside it. Clips nest (intersected).
    void pushClip(const Rect& r);
    void popClip();
    // Appends another list's vertices (drawn after this list's, e.g. popups over widgets).
    void append(const DrawList& other);
    void rect(const Rect& r, glm::vec4 colour);
    // Any convex quadrilateral, corners in order (solid colour).
    void quadrilateral(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d, glm::vec4 colour);
    // A straight segment `width` pixels wide (a quad along it; no end caps).
    void line(glm::vec2 from, glm::vec2 to, float width, glm::vec4 colour);
    // Draws one line with its top-left corner at `topLeft` (the baseline sits ascent() below it);
    // returns the x just after the last glyph.
    float text(glm::vec2 topLeft, std::string_view utf8, glm::vec4 colour);
    // As text(), but cuts the string (adding "...") so that it ends before maxX.
    float textClipped(glm::vec2 topLeft, std::string_view utf8, glm::vec4 colour, float maxX);

    const FontAtlas& font() const { return *mFont; }
    const std::vector<UiVertex>& vertices() const { return mVertices; }

private:
    void quad(glm::vec2 p0, glm::vec2 p1, glm::vec2 uv0, glm::vec2 uv1, std::uint32_t colour);

    const FontAtlas* mFont;
    std::vector<UiVertex> mVertices;  // six per quad (two triangles)
    std::vector<Rect> mClips;
    std::vector<GlyphQuad> mScratch;
};

// Owns the atlas texture, the program (shaders/ui/text.vert, text.frag), a vertex array and a vertex
// buffer that grows as needed. Needs a current GL 4.5 context.
class TextRenderer {
public:
    explicit TextRenderer(const FontAtlas& font);

    // Draws the list over whatever is in the bound framebuffer, alpha-blended, in one glDrawArrays.
    // Saves and restores the blend, depth, cull, scissor and program state it changes.
    void draw(const DrawList& list, glm::ivec2 framebufferSize);

private:
    gl::Texture mAtlas;
    gl::Program mProgram;
    gl::VertexArray mVertexArray;
    gl::Buffer mVertices;
};

}  // namespace viz::ui
