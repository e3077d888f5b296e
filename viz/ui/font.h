// A glyph atlas baked once at start-up from a TrueType file with stb_truetype, and the layout of a
// line of UTF-8 text into textured quads. CPU only: the GL side lives in ui/text_renderer.h.
// Coordinates: window pixels, origin at the top-left, y down; atlas uv in [0,1]^2 with v = 0 the top
// row of the coverage bitmap (the row GL receives first).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace viz::ui {

// One glyph's quad on screen and in the atlas.
struct GlyphQuad {
    glm::vec2 p0, p1;    // screen pixels, top-left and bottom-right
    glm::vec2 uv0, uv1;  // atlas uv of the same corners
};

class FontAtlas {
public:
    // The font the app uses (Debian package fonts-dejavu-core).
    static constexpr const char* kDefaultFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    // $AIRLIGHT_FONT when set, else kDefaultFontPath.
    static std::string defaultFontPath();

    // Bakes printable ASCII, Latin-1, Greek and a few math symbols at pixelHeight (ascender to
    // descender, in pixels). Throws InputError naming the path when the file is missing or not a font.
    static FontAtlas bake(const std::string& ttfPath, float pixelHeight);

    // Single-channel coverage, atlasWidth() * atlasHeight() bytes, row 0 at the top.
    const std::vector<std::uint8_t>& coverage() const { return mCoverage; }
    int atlasWidth() const { return mWidth; }
    int atlasHeight() const { return mHeight; }
    // The centre of a block of fully covered texels: solid rectangles sample here, so rectangles and
    // glyphs share one texture and one draw call.
    glm::vec2 whiteUv() const { return mWhiteUv; }

    float pixelHeight() const { return mPixelHeight; }
    float ascent() const { return mAscent; }    // baseline to the top of the tallest glyph, > 0
    float descent() const { return mDescent; }  // baseline to the bottom, < 0
    float lineHeight() const { return mAscent - mDescent + mLineGap; }

    bool hasGlyph(char32_t codepoint) const { return findGlyph(codepoint) != nullptr; }
    float advance(char32_t codepoint) const;  // pen advance in pixels; unknown code points draw as '?'
    // Width in pixels of a line of UTF-8 text (sum of advances; no kerning).
    float measure(std::string_view utf8) const;
    // Appends one quad per visible glyph, the pen starting at `baseline` (x = left edge, y = baseline).
    // Returns the pen x after the last glyph.
    float layout(std::string_view utf8, glm::vec2 baseline, std::vector<GlyphQuad>& out) const;

private:
    struct Glyph {
        char32_t codepoint = 0;
        glm::vec2 atlas0{0.0f}, atlas1{0.0f};  // box in atlas texels
        glm::vec2 offset0{0.0f}, offset1{0.0f};  // quad corners relative to the pen, pixels
        float advance = 0.0f;
    };
    const Glyph* findGlyph(char32_t codepoint) const;
    const Glyph& glyphOrFallback(char32_t codepoint) const;

    std::vector<Glyph> mGlyphs;  // sorted by code point
    std::vector<std::uint8_t> mCoverage;
    int mWidth = 0;
    int mHeight = 0;
    glm::vec2 mWhiteUv{0.0f};
    float mPixelHeight = 0.0f;
    float mAscent = 0.0f;
    float mDescent = 0.0f;
    float mLineGap = 0.0f;
};

// Decodes the next code point of a UTF-8 string starting at `pos` and advances pos; malformed bytes
// decode as U+FFFD one byte at a time.
char32_t nextCodepoint(std::string_view utf8, std::size_t& pos);

}  // namespace viz::ui
