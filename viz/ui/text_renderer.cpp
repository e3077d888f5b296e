#include "ui/text_renderer.h"

#include <algorithm>
#include <cstddef>
#include <string>

namespace viz::ui {

std::uint32_t packColour(glm::vec4 rgba) {
    const glm::uvec4 c = glm::uvec4(glm::clamp(rgba, 0.0f, 1.0f) * 255.0f + 0.5f);
    // Little-endian memory order r, g, b, a matches a 4 x GL_UNSIGNED_BYTE attribute.
    return c.r | (c.g << 8) | (c.b << 16) | (c.a << 24);
}

// ---- DrawList (CPU) ----

void DrawList::pushClip(const Rect& r) {
    Rect c = r;
    if (!mClips.empty()) {
        c.min = glm::max(c.min, mClips.back().min);
        c.max = glm::min(c.max, mClips.back().max);
    }
    mClips.push_back(c);
}

void DrawList::popClip() {
    if (!mClips.empty()) mClips.pop_back();
}

void DrawList::append(const DrawList& other) {
    mVertices.insert(mVertices.end(), other.mVertices.begin(), other.mVertices.end());
}

void DrawList::quad(glm::vec2 p0, glm::vec2 p1, glm::vec2 uv0, glm::vec2 uv1, std::uint32_t colour) {
    if (!mClips.empty()) {
        // Cut the quad to the clip rectangle, moving the uvs in proportion.
        const Rect& c = mClips.back();
        const glm::vec2 q0 = glm::max(p0, c.min), q1 = glm::min(p1, c.max);
        if (q0.x >= q1.x || q0.y >= q1.y) return;
        const glm::vec2 size = p1 - p0;
        const glm::vec2 t0 = glm::vec2(size.x > 0 ? (q0.x - p0.x) / size.x : 0, size.y > 0 ? (q0.y - p0.y) / size.y : 0);
        const glm::vec2 t1 = glm::vec2(size.x > 0 ? (q1.x - p0.x) / size.x : 1, size.y > 0 ? (q1.y - p0.y) / size.y : 1);
        const glm::vec2 w0 = uv0 + (uv1 - uv0) * t0, w1 = uv0 + (uv1 - uv0) * t1;
        p0 = q0, p1 = q1, uv0 = w0, uv1 = w1;
    }
    const UiVertex a{p0, uv0, colour};
    const UiVertex b{{p1.x, p0.y}, {uv1.x, uv0.y}, colour};
    const UiVertex c{p1, uv1, colour};
    const UiVertex d{{p0.x, p1.y}, {uv0.x, uv1.y}, colour};
    mVertices.insert(mVertices.end(), {a, b, c, a, c, d});
}

void DrawList::rect(const Rect& r, glm::vec4 colour) {
    const glm::vec2 uv = mFont->whiteUv();
    quad(r.min, r.max, uv, uv, packColour(colour));
}

void DrawList::quadrilateral(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d, glm::vec4 colour) {
    if (!mClips.empty()) {
        const Rect& clip = mClips.back();
        const glm::vec2 lo = glm::min(glm::min(a, b), glm::min(c, d)), hi = glm::max(glm::max(a, b), glm::max(c, d));
        if (hi.x <= clip.min.x || hi.y <= clip.min.y || lo.x >= clip.max.x || lo.y >= clip.max.y) return;
    }
    const glm::vec2 uv = mFont->whiteUv();
    const std::uint32_t packed = packColour(colour);
    const UiVertex va{a, uv, packed}, vb{b, uv, packed}, vc{c, uv, packed}, vd{d, uv, packed};
    mVertices.insert(mVertices.end(), {va, vb, vc, va, vc, vd});
}

void DrawList::line(glm::vec2 from, glm::vec2 to, float width, glm::vec4 colour) {
    const glm::vec2 along = to - from;
    const float length = glm::length(along);
    if (!(length > 0.0f)) return;
    const glm::vec2 side = glm::vec2(-along.y, along.x) * (0.5f * width / length);
    quadrilateral(from - side, to - side, to + side, from + side, colour);
}

float DrawList::text(glm::vec2 topLeft, std::string_view utf8, glm::vec4 colour) {
    mScratch.clear();
    const float end = mFont->layout(utf8, {topLeft.x, topLeft.y + mFont->ascent()}, mScratch);
    const std::uint32_t c = packColour(colour);
    for (const GlyphQuad& g : mScratch) quad(g.p0, g.p1, g.uv0, g.uv1, c);
    return end;
}

float DrawList::textClipped(glm::vec2 topLeft, std::string_view utf8, glm::vec4 colour, float maxX) {
    const float available = maxX - topLeft.x;
    if (mFont->measure(utf8) <= available) return text(topLeft, utf8, colour);
    const float ellipsis = mFont->measure("...");
    // Keep whole code points: walk the UTF-8 string and stop before the one that would not fit.
    float width = 0.0f;
    std::size_t cut = 0;
    for (std::size_t pos = 0; pos < utf8.size();) {
        width += mFont->advance(nextCodepoint(utf8, pos));
        if (width + ellipsis > available) break;
        cut = pos;
    }
    std::string shortened(utf8.substr(0, cut));
    shortened += "...";
    return text(topLeft, shortened, colour);
}

// ---- TextRenderer (GL) ----

TextRenderer::TextRenderer(const FontAtlas& font) {
    mAtlas = gl::Texture::create({.target = GL_TEXTURE_2D,
                                  .format = GL_R8,
                                  .size = {font.atlasWidth(), font.atlasHeight(), 1},
                                  .label = "ui.glyph_atlas"});
    // Rows are one byte per texel and the width need not be a multiple of 4.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    mAtlas.upload(GL_RED, GL_UNSIGNED_BYTE, font.coverage().data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // Glyph quads map one texel to one pixel at integer pen positions; nearest keeps them sharp.
    mAtlas.setFilter(GL_NEAREST, GL_NEAREST);
    mAtlas.setWrap(GL_CLAMP_TO_EDGE);

    mProgram = gl::Program::compile({.stages = {"ui/text.vert", "ui/text.frag"}, .label = "ui.text"});
    mVertexArray = gl::VertexArray::create("ui.text_vao");
}

void TextRenderer::draw(const DrawList& list, glm::ivec2 framebufferSize) {
    const auto& vertices = list.vertices();
    if (vertices.empty()) return;
    const std::size_t bytes = vertices.size() * sizeof(UiVertex);
    if (mVertices.bytes() < bytes) {
        // Immutable storage cannot grow: replace it with one twice as large as needed.
        mVertices = gl::Buffer::create({.bytes = std::max<std::size_t>(bytes * 2, 64 * 1024),
                                        .flags = GL_DYNAMIC_STORAGE_BIT,
                                        .label = "ui.text_vertices"});
        mVertexArray.vertexBuffer(0, mVertices, 0, sizeof(UiVertex));
        mVertexArray.attribute(0, 0, 2, GL_FLOAT, offsetof(UiVertex, position));
        mVertexArray.attribute(1, 0, 2, GL_FLOAT, offsetof(UiVertex, uv));
        mVertexArray.attribute(2, 0, 4, GL_UNSIGNED_BYTE, offsetof(UiVertex, colour), true);
    }
    mVertices.upload(0, bytes, vertices.data());

    // Save what we change (docs/architecture.md#gl-state: the UI renderer restores state around itself).
    GLint program = 0, vertexArray = 0, blendSrc = 0, blendDst = 0, blendSrcA = 0, blendDstA = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
    glGetIntegerv(GL_BLEND_SRC_RGB, &blendSrc);
    glGetIntegerv(GL_BLEND_DST_RGB, &blendDst);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blendSrcA);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blendDstA);
    const GLboolean blend = glIsEnabled(GL_BLEND);
    const GLboolean depth = glIsEnabled(GL_DEPTH_TEST);
    const GLboolean cull = glIsEnabled(GL_CULL_FACE);
    const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);

    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, framebufferSize.x, framebufferSize.y);

    mProgram.set("uViewport", glm::vec2(framebufferSize));
    mProgram.use();
    mAtlas.bindUnit(0);
    glBindSampler(0, 0);
    mVertexArray.bind();
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));

    glBindVertexArray(static_cast<GLuint>(vertexArray));
    glUseProgram(static_cast<GLuint>(program));
    glBlendFuncSeparate(static_cast<GLenum>(blendSrc), static_cast<GLenum>(blendDst), static_cast<GLenum>(blendSrcA),
                        static_cast<GLenum>(blendDstA));
    if (!blend) glDisable(GL_BLEND);
    if (depth) glEnable(GL_DEPTH_TEST);
    if (cull) glEnable(GL_CULL_FACE);
    if (scissor) glEnable(GL_SCISSOR_TEST);
}

}  // namespace viz::ui
