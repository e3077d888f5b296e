// FontAtlas (stb_truetype bake of DejaVu Sans) and the CPU side of the text batch (DrawList).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "ui/font.h"
#include "ui/text_renderer.h"
#include "temp_dir.h"

namespace {

using viz::ui::FontAtlas;

const FontAtlas& font16() {
    static const FontAtlas atlas = FontAtlas::bake(FontAtlas::kDefaultFontPath, 16.0f);
    return atlas;
}

// Sum of coverage over the atlas texels a quad samples.
long coverageUnder(const FontAtlas& atlas, const viz::ui::GlyphQuad& q) {
    const int x0 = int(q.uv0.x * float(atlas.atlasWidth()) + 0.5f);
    const int x1 = int(q.uv1.x * float(atlas.atlasWidth()) + 0.5f);
    const int y0 = int(q.uv0.y * float(atlas.atlasHeight()) + 0.5f);
    const int y1 = int(q.uv1.y * float(atlas.atlasHeight()) + 0.5f);
    long sum = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += atlas.coverage()[std::size_t(y * atlas.atlasWidth() + x)];
    return sum;
}

}  // namespace

TEST(FontAtlas, MissingFileIsAnInputErrorNamingThePath) {
    try {
        FontAtlas::bake("/nonexistent/dir/NoSuchFont.ttf", 16.0f);
        FAIL() << "expected InputError";
    } catch (const viz::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/NoSuchFont.ttf"), std::string::npos) << e.what();
    }
}

TEST(FontAtlas, NonFontFileIsAnInputError) {
    const viz::testing::TempDir temp("not_a_font");
    const auto path = temp / "not_a_font.ttf";
    {
        std::ofstream f(path, std::ios::binary);
        f << "this is plain text, not a TrueType font at all";
    }
    EXPECT_THROW(FontAtlas::bake(path.string(), 16.0f), viz::InputError);
}

TEST(FontAtlas, BakesPrintableAsciiAndGreek) {
    const FontAtlas& f = font16();
    for (char32_t c = 0x20; c < 0x7F; ++c) EXPECT_TRUE(f.hasGlyph(c)) << "code point " << unsigned(c);
    EXPECT_TRUE(f.hasGlyph(U'σ'));
    EXPECT_TRUE(f.hasGlyph(U'θ'));
    EXPECT_TRUE(f.hasGlyph(U'→'));
    EXPECT_FALSE(f.hasGlyph(U'中'));  // not baked
    EXPECT_EQ(f.coverage().size(), std::size_t(f.atlasWidth()) * std::size_t(f.atlasHeight()));
}

TEST(FontAtlas, VerticalMetricsSpanThePixelHeight) {
    // stb scales the font so that ascender - descender equals the requested pixel height.
    const FontAtlas& f = font16();
    EXPECT_NEAR(f.ascent() - f.descent(), 16.0f, 1e-3f);
    EXPECT_GT(f.ascent(), 0.0f);
    EXPECT_LT(f.descent(), 0.0f);
    EXPECT_GE(f.lineHeight(), 16.0f);
}

TEST(FontAtlas, AdvancesScaleWithPixelHeight) {
    const FontAtlas big = FontAtlas::bake(FontAtlas::kDefaultFontPath, 32.0f);
    EXPECT_NEAR(big.advance(U'M'), 2.0f * font16().advance(U'M'), 0.5f);
    EXPECT_GT(font16().advance(U'W'), font16().advance(U'i'));
}

TEST(FontAtlas, WhiteTexelIsOpaque) {
    const FontAtlas& f = font16();
    const int x = int(f.whiteUv().x * float(f.atlasWidth()));
    const int y = int(f.whiteUv().y * float(f.atlasHeight()));
    // The texel and its 4-neighbours (linear filtering may touch them) are fully covered.
    for (auto [dx, dy] : {std::pair{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        EXPECT_EQ(f.coverage()[std::size_t((y + dy) * f.atlasWidth() + x + dx)], 255);
    }
}

TEST(FontAtlas, MeasureIsTheSumOfAdvances) {
    const FontAtlas& f = font16();
    EXPECT_EQ(f.measure(""), 0.0f);
    EXPECT_FLOAT_EQ(f.measure("AB"), f.advance(U'A') + f.advance(U'B'));
    EXPECT_FLOAT_EQ(f.measure("σ=1"), f.advance(U'σ') + f.advance(U'=') + f.advance(U'1'));
    // A code point that was not baked is drawn (and measured) as '?'.
    EXPECT_FLOAT_EQ(f.measure("中"), f.advance(U'?'));
}

TEST(FontAtlas, LayoutEmitsOneQuadPerVisibleGlyphAtOneTexelPerPixel) {
    const FontAtlas& f = font16();
    std::vector<viz::ui::GlyphQuad> quads;
    const float end = f.layout("a b", {10.0f, 20.0f}, quads);
    ASSERT_EQ(quads.size(), 2u);  // the space has no quad
    EXPECT_FLOAT_EQ(end, 10.0f + f.measure("a b"));
    EXPECT_LT(quads[0].p1.x, quads[1].p0.x);
    const glm::vec2 atlasSize{float(f.atlasWidth()), float(f.atlasHeight())};
    for (const auto& q : quads) {
        EXPECT_GE(q.uv0.x, 0.0f);
        EXPECT_LE(q.uv1.x, 1.0f);
        EXPECT_GE(q.uv0.y, 0.0f);
        EXPECT_LE(q.uv1.y, 1.0f);
        EXPECT_NEAR(q.p1.x - q.p0.x, (q.uv1.x - q.uv0.x) * atlasSize.x, 1e-3f);
        EXPECT_NEAR(q.p1.y - q.p0.y, (q.uv1.y - q.uv0.y) * atlasSize.y, 1e-3f);
        // 'a' and 'b' sit on the baseline: they reach above it and not far below.
        EXPECT_LT(q.p0.y, 20.0f);
        EXPECT_LE(q.p1.y, 20.0f + 2.0f);
        EXPECT_GT(coverageUnder(f, q), 255) << "glyph box is empty";
    }
}

TEST(FontAtlas, Utf8Decoding) {
    const std::string s = "a\xCF\x83\xE2\x86\x92";  // a, sigma, rightwards arrow
    std::size_t pos = 0;
    EXPECT_EQ(viz::ui::nextCodepoint(s, pos), U'a');
    EXPECT_EQ(viz::ui::nextCodepoint(s, pos), U'σ');
    EXPECT_EQ(viz::ui::nextCodepoint(s, pos), U'→');
    EXPECT_EQ(pos, s.size());
    const std::string truncated = "\xCF";
    pos = 0;
    EXPECT_EQ(viz::ui::nextCodepoint(truncated, pos), char32_t(0xFFFD));
    EXPECT_EQ(pos, 1u);
}

TEST(DrawList, RectAndTextEmitTwoTrianglesPerQuad) {
    viz::ui::DrawList list(font16());
    list.rect({{1.0f, 2.0f}, {11.0f, 7.0f}}, {1, 0, 0, 1});
    ASSERT_EQ(list.vertices().size(), 6u);
    for (const auto& v : list.vertices()) {
        EXPECT_EQ(v.uv, font16().whiteUv());
        EXPECT_EQ(v.colour, viz::ui::packColour({1, 0, 0, 1}));
        EXPECT_TRUE(v.position.x == 1.0f || v.position.x == 11.0f);
        EXPECT_TRUE(v.position.y == 2.0f || v.position.y == 7.0f);
    }
    list.text({0.0f, 0.0f}, "ab c", {1, 1, 1, 1});
    EXPECT_EQ(list.vertices().size(), 6u + 3u * 6u);
    list.clear();
    EXPECT_TRUE(list.vertices().empty());
}

TEST(DrawList, ClippedTextEndsBeforeTheLimit) {
    viz::ui::DrawList list(font16());
    const std::string longText = "a fairly long line that certainly does not fit in sixty pixels";
    const float end = list.textClipped({5.0f, 0.0f}, longText, {1, 1, 1, 1}, 65.0f);
    EXPECT_LE(end, 65.0f);
    EXPECT_GT(end, 5.0f + font16().measure("..."));
    for (const auto& v : list.vertices()) EXPECT_LE(v.position.x, 65.0f + 1.0f);
    // A short text is not cut.
    viz::ui::DrawList shortList(font16());
    EXPECT_FLOAT_EQ(shortList.textClipped({0.0f, 0.0f}, "ok", {1, 1, 1, 1}, 100.0f), font16().measure("ok"));
}

TEST(PackColour, MemoryOrderIsRgba) {
    const std::uint32_t c = viz::ui::packColour({1.0f, 0.0f, 0.5f, 0.25f});
    const auto* bytes = reinterpret_cast<const unsigned char*>(&c);
    EXPECT_EQ(bytes[0], 255);
    EXPECT_EQ(bytes[1], 0);
    EXPECT_EQ(bytes[2], 128);
    EXPECT_EQ(bytes[3], 64);
}
