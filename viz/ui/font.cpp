#include "ui/font.h"

#include <stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "core/error.h"

namespace viz::ui {

namespace {

// Code point ranges we bake: ASCII, Latin-1, Greek (sigma, theta, ...), and a few symbols that notes
// use (arrows, <=, >=, middle dot, times, ellipsis, infinity, integral).
struct Range {
    int first;
    int count;
};
constexpr Range kRanges[] = {
    {0x20, 0x7F - 0x20}, {0xA0, 0x100 - 0xA0}, {0x391, 0x3CA - 0x391}, {0x2026, 1},
    {0x2190, 4},         {0x2211, 2},          {0x221A, 1},          {0x221E, 1},
    {0x222B, 1},         {0x2248, 1},          {0x2260, 1},          {0x2264, 2},
};

// Block of opaque texels written below the packed glyphs for solid rectangles.
constexpr int kWhiteBlock = 4;

std::vector<unsigned char> readFile(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError("font file not found: " + path + " (install fonts-dejavu-core)");
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

}  // namespace

char32_t nextCodepoint(std::string_view s, std::size_t& pos) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    const unsigned char b0 = byte(pos);
    int extra = 0;
    char32_t cp = 0;
    if (b0 < 0x80) {
        ++pos;
        return b0;
    } else if ((b0 & 0xE0) == 0xC0) {
        extra = 1;
        cp = b0 & 0x1F;
    } else if ((b0 & 0xF0) == 0xE0) {
        extra = 2;
        cp = b0 & 0x0F;
    } else if ((b0 & 0xF8) == 0xF0) {
        extra = 3;
        cp = b0 & 0x07;
    } else {
        ++pos;
        return 0xFFFD;
    }
    if (pos + static_cast<std::size_t>(extra) >= s.size()) {
        ++pos;
        return 0xFFFD;
    }
    for (int i = 1; i <= extra; ++i) {
        const unsigned char b = byte(pos + static_cast<std::size_t>(i));
        if ((b & 0xC0) != 0x80) {
            ++pos;
            return 0xFFFD;
        }
        cp = (cp << 6) | (b & 0x3F);
    }
    pos += static_cast<std::size_t>(extra) + 1;
    return cp;
}

std::string FontAtlas::defaultFontPath() {
    if (const char* env = std::getenv("AIRLIGHT_FONT"); env != nullptr && env[0] != '\0') {
        return env;
    }
    return kDefaultFontPath;
}

FontAtlas FontAtlas::bake(const std::string& ttfPath, float pixelHeight) {
    VIZ_CHECK(pixelHeight > 1.0f && pixelHeight < 512.0f, "font pixel height out of range");
    const std::vector<unsigned char> data = readFile(ttfPath);
    if (data.size() < 12 || stbtt_GetFontOffsetForIndex(data.data(), 0) < 0) {
        throw InputError("not a TrueType font: " + ttfPath);
    }
    stbtt_fontinfo info;
    if (!stbtt_InitFont(&info, data.data(), stbtt_GetFontOffsetForIndex(data.data(), 0))) {
        throw InputError("not a TrueType font: " + ttfPath);
    }

    int total = 0;
    for (const Range& r : kRanges) total += r.count;
    std::vector<stbtt_packedchar> packed(static_cast<std::size_t>(total));

    FontAtlas atlas;
    atlas.mPixelHeight = pixelHeight;
    // Grow the atlas until every glyph fits; one oversampled texel per pixel keeps small text crisp
    // at integer pen positions.
    for (int size = 256; size <= 4096; size *= 2) {
        const int packHeight = size;
        const int fullHeight = size + kWhiteBlock + 2;
        std::vector<std::uint8_t> pixels(static_cast<std::size_t>(size) * static_cast<std::size_t>(fullHeight), 0);
        stbtt_pack_context pc;
        if (!stbtt_PackBegin(&pc, pixels.data(), size, packHeight, size, 1, nullptr)) continue;
        std::vector<stbtt_pack_range> ranges;
        int offset = 0;
        for (const Range& r : kRanges) {
            stbtt_pack_range pr{};
            pr.font_size = pixelHeight;
            pr.first_unicode_codepoint_in_range = r.first;
            pr.num_chars = r.count;
            pr.chardata_for_range = packed.data() + offset;
            ranges.push_back(pr);
            offset += r.count;
        }
        const int ok = stbtt_PackFontRanges(&pc, data.data(), 0, ranges.data(), static_cast<int>(ranges.size()));
        stbtt_PackEnd(&pc);
        if (!ok) continue;

        // Rows below the packed area belong to us: one opaque block for solid rectangles.
        for (int y = packHeight + 1; y < packHeight + 1 + kWhiteBlock; ++y) {
            for (int x = 1; x < 1 + kWhiteBlock; ++x) {
                pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + static_cast<std::size_t>(x)] = 255;
            }
        }
        atlas.mWidth = size;
        atlas.mHeight = fullHeight;
        atlas.mCoverage = std::move(pixels);
        atlas.mWhiteUv = {(1.0f + 0.5f * kWhiteBlock) / float(size),
                          (float(packHeight) + 1.0f + 0.5f * kWhiteBlock) / float(fullHeight)};
        break;
    }
    VIZ_CHECK(atlas.mWidth > 0, "glyph atlas does not fit in 4096x4096");

    int index = 0;
    for (const Range& r : kRanges) {
        for (int i = 0; i < r.count; ++i, ++index) {
            const stbtt_packedchar& pc = packed[static_cast<std::size_t>(index)];
            const char32_t cp = static_cast<char32_t>(r.first + i);
            // Skip code points the font lacks (stb packs them as empty boxes with zero advance).
            if (cp != U' ' && stbtt_FindGlyphIndex(&info, static_cast<int>(cp)) == 0) continue;
            Glyph g;
            g.codepoint = cp;
            g.atlas0 = {pc.x0, pc.y0};
            g.atlas1 = {pc.x1, pc.y1};
            g.offset0 = {pc.xoff, pc.yoff};
            g.offset1 = {pc.xoff2, pc.yoff2};
            g.advance = pc.xadvance;
            atlas.mGlyphs.push_back(g);
        }
    }
    std::sort(atlas.mGlyphs.begin(), atlas.mGlyphs.end(),
              [](const Glyph& a, const Glyph& b) { return a.codepoint < b.codepoint; });

    // Vertical metrics in font units, scaled the way the packer scaled the glyphs.
    int ascent = 0, descent = 0, lineGap = 0;
    stbtt_GetFontVMetrics(&info, &ascent, &descent, &lineGap);
    const float scale = stbtt_ScaleForPixelHeight(&info, pixelHeight);
    atlas.mAscent = float(ascent) * scale;
    atlas.mDescent = float(descent) * scale;
    atlas.mLineGap = float(lineGap) * scale;
    VIZ_CHECK(atlas.hasGlyph(U'?'), "font has no '?' glyph for the fallback");
    return atlas;
}

const FontAtlas::Glyph* FontAtlas::findGlyph(char32_t cp) const {
    auto it = std::lower_bound(mGlyphs.begin(), mGlyphs.end(), cp,
                               [](const Glyph& g, char32_t c) { return g.codepoint < c; });
    return it != mGlyphs.end() && it->codepoint == cp ? &*it : nullptr;
}

const FontAtlas::Glyph& FontAtlas::glyphOrFallback(char32_t cp) const {
    if (const Glyph* g = findGlyph(cp)) return *g;
    return *findGlyph(U'?');
}

float FontAtlas::advance(char32_t cp) const { return glyphOrFallback(cp).advance; }

float FontAtlas::measure(std::string_view utf8) const {
    float width = 0.0f;
    for (std::size_t pos = 0; pos < utf8.size();) width += advance(nextCodepoint(utf8, pos));
    return width;
}

float FontAtlas::layout(std::string_view utf8, glm::vec2 baseline, std::vector<GlyphQuad>& out) const {
    const glm::vec2 texel = 1.0f / glm::vec2(float(mWidth), float(mHeight));
    float x = baseline.x;
    for (std::size_t pos = 0; pos < utf8.size();) {
        const Glyph& g = glyphOrFallback(nextCodepoint(utf8, pos));
        if (g.atlas1.x > g.atlas0.x && g.atlas1.y > g.atlas0.y) {
            // Snap the pen to whole pixels so that one atlas texel lands on one screen pixel.
            const glm::vec2 pen{std::round(x), std::round(baseline.y)};
            out.push_back({pen + g.offset0, pen + g.offset1, g.atlas0 * texel, g.atlas1 * texel});
        }
        x += g.advance;
    }
    return x;
}

}  // namespace viz::ui
