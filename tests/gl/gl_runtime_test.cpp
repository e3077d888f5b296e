// Tests of the GL runtime on a headless EGL context: context version, RAII ownership,
// texture/buffer round trips (row order), shader loading (includes, defines, error locations) and
// the stage clock.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/gl_test_fixture.h"
#include "platform/context_egl.h"

namespace viz::gl {
namespace {

// One context per suite (GlTest); a missing GL 4.5 skips unless VIZ_REQUIRE_GL=1.
using GlRuntime = GlTest;

// 1-based line of the first line of a shader file containing `marker`, read straight from the file.
int lineContaining(const std::string& relativePath, const std::string& marker) {
    std::ifstream in(shaderDirectory() + "/" + relativePath);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.find(marker) != std::string::npos)
            return n;
    }
    return -1;
}

// ---- context ----

TEST_F(GlRuntime, ContextIsOpenGl45CoreDebug) {
    const ContextInfo info = contextInfo();
    EXPECT_GE(info.major * 10 + info.minor, 45) << info.version;
    EXPECT_TRUE(info.core);
    EXPECT_TRUE(info.debug);
    EXPECT_FALSE(context()->renderer().empty());
    EXPECT_NO_THROW(requireGl45());
}

TEST_F(GlRuntime, DebugOutputCountsApiErrors) {
    // A deliberate GL_INVAL_ENUM: the counter must see it, or the per-test zero check means nothing.
    glEnable(GL_TEXTURE_2D);  // not a capability in core profile
    EXPECT_EQ(debugErrorCount(), 1);
    resetDebugErrorCount();
}

TEST_F(GlRuntime, SecondContextOnTheSameDisplayLeavesTheFirstWorking) {
    {
        std::unique_ptr<HeadlessContext> other = HeadlessContext::create(/*debug=*/false);
        HeadlessContext moved = std::move(*other);
        other.reset();  // the moved-from context releases nothing
        moved.makeCurrent();
        EXPECT_GE(contextInfo().major, 4);
    }
    // Both are gone; the display must still be alive for the suite's context.
    context()->makeCurrent();
    Texture t = Texture::create({.format = GL_R32F, .size = {1, 1, 1}, .label = "test.after_second"});
    const float v = 1.5f;
    t.upload(GL_RED, GL_FLOAT, &v);
    EXPECT_EQ(readTexture(t).at(0, 0), 1.5f);
    const std::string platform = context()->platform();
    EXPECT_TRUE(platform == "surfaceless" || platform == "device") << platform;
}

// ---- ownership ----

int gDestroyCalls = 0;
struct CountingTraits {
    static void destroy(GLuint) { ++gDestroyCalls; }
};

TEST_F(GlRuntime, HandleMoveTransfersOwnershipAndMovedFromDeletesNothing) {
    gDestroyCalls = 0;
    {
        Handle<CountingTraits> a(42);
        Handle<CountingTraits> b(std::move(a));
        EXPECT_EQ(a.get(), 0u);
        EXPECT_EQ(b.get(), 42u);
        Handle<CountingTraits> c(7);
        c = std::move(b);  // c's old name 7 is deleted now, 42 moves over
        EXPECT_EQ(gDestroyCalls, 1);
        EXPECT_EQ(c.get(), 42u);
        EXPECT_EQ(b.get(), 0u);
    }
    // Only c (holding 42) deleted something at scope exit; a and b were empty.
    EXPECT_EQ(gDestroyCalls, 2);
}

TEST_F(GlRuntime, MovedTextureKeepsTheGlObjectAlive) {
    GLuint name = 0;
    {
        Texture a = Texture::create({.format = GL_RGBA8, .size = {4, 4, 1}, .label = "test.move"});
        name = a.id();
        ASSERT_TRUE(glIsTexture(name));
        Texture b = std::move(a);
        EXPECT_EQ(a.id(), 0u);
        EXPECT_EQ(b.id(), name);
        { Texture moved = std::move(a); }  // destroying an empty texture deletes nothing
        EXPECT_TRUE(glIsTexture(name));
        Buffer buf = Buffer::create({.bytes = 16, .label = "test.move_buffer"});
        Buffer other = std::move(buf);
        EXPECT_EQ(buf.id(), 0u);
        EXPECT_TRUE(glIsBuffer(other.id()));
    }
    EXPECT_FALSE(glIsTexture(name));
}

TEST_F(GlRuntime, LabelReachesTheDriver) {
    Texture t = Texture::create({.format = GL_R32F, .size = {2, 2, 1}, .label = "test.labelled"});
    char label[64] = {};
    GLsizei length = 0;
    glGetObjectLabel(GL_TEXTURE, t.id(), sizeof label, &length, label);
    EXPECT_EQ(std::string(label, static_cast<size_t>(length)), "test.labelled");
}

// ---- textures, buffers, readback ----

TEST_F(GlRuntime, TextureRoundTripFlipsRows) {
    // 5 x 3 (odd width catches row alignment); GL's row 0 is the bottom, the first row we upload.
    const int w = 5, h = 3;
    std::vector<float> data;
    for (int glRow = 0; glRow < h; ++glRow) {
        for (int x = 0; x < w; ++x) {
            data.insert(data.end(), {float(x), float(glRow), float(x + 10 * glRow), 0.25f});
        }
    }
    Texture t = Texture::create({.format = GL_RGBA32F, .size = {w, h, 1}, .label = "test.rgba"});
    t.upload(GL_RGBA, GL_FLOAT, data.data());
    const Image img = readTexture(t);
    ASSERT_EQ(img.width, w);
    ASSERT_EQ(img.height, h);
    ASSERT_EQ(img.channels, 4);
    for (int y = 0; y < h; ++y) {
        const int glRow = h - 1 - y;  // image row 0 is the top
        for (int x = 0; x < w; ++x) {
            EXPECT_EQ(img.at(x, y, 0), float(x));
            EXPECT_EQ(img.at(x, y, 1), float(glRow));
            EXPECT_EQ(img.at(x, y, 2), float(x + 10 * glRow));
            EXPECT_EQ(img.at(x, y, 3), 0.25f);
        }
    }
}

TEST_F(GlRuntime, ReadbackKeepsChannelCountOfTheFormat) {
    const std::vector<float> values = {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f};  // 3 x 2, R
    Texture r = Texture::create({.format = GL_R32F, .size = {3, 2, 1}, .label = "test.r32f"});
    r.upload(GL_RED, GL_FLOAT, values.data());
    const Image ri = readTexture(r);
    EXPECT_EQ(ri.channels, 1);
    EXPECT_EQ(ri.at(0, 0), 4.0f);  // top-left = first texel of GL row 1
    EXPECT_EQ(ri.at(2, 1), 3.0f);

    Texture rg = Texture::create({.format = GL_RG32F, .size = {3, 1, 1}, .label = "test.rg32f"});
    rg.upload(GL_RG, GL_FLOAT, values.data());
    const Image rgi = readTexture(rg);
    EXPECT_EQ(rgi.channels, 2);
    EXPECT_EQ(rgi.at(1, 0, 1), 4.0f);

    const std::vector<GLuint> bits = {0xffffffffu, 7u, 0u, 1u << 31};
    Texture u = Texture::create({.format = GL_R32UI, .size = {2, 2, 1}, .label = "test.r32ui"});
    u.upload(GL_RED_INTEGER, GL_UNSIGNED_INT, bits.data());
    const Image ui = readTexture(u);
    EXPECT_EQ(ui.channels, 1);
    EXPECT_EQ(ui.at(1, 1), 7.0f);
    EXPECT_EQ(ui.at(1, 0), float(1u << 31));

    Texture d = Texture::create(
        {.format = GL_DEPTH_COMPONENT32F, .size = {2, 2, 1}, .label = "test.depth"});
    d.clear(glm::vec4(0.375f));
    const Image di = readTexture(d);
    EXPECT_EQ(di.channels, 1);
    EXPECT_EQ(di.at(1, 1), 0.375f);
}

TEST_F(GlRuntime, ReadbackOfOneLayer) {
    Texture arr = Texture::create({.target = GL_TEXTURE_2D_ARRAY,
                                   .format = GL_R32F,
                                   .size = {2, 2, 3},
                                   .label = "test.array"});
    for (int layer = 0; layer < 3; ++layer) {
        const float v[4] = {float(layer), float(layer), float(layer), float(layer) + 0.5f};
        arr.uploadRegion({0, 0, layer}, {2, 2, 1}, GL_RED, GL_FLOAT, v);
    }
    EXPECT_EQ(arr.layers(), 3);
    EXPECT_EQ(readTexture(arr, 0, 2).at(1, 0), 2.5f);  // GL (1,1) is image (1,0)
    EXPECT_EQ(readTexture(arr, 0, 1).at(0, 1), 1.0f);

    Texture cube = Texture::create({.target = GL_TEXTURE_CUBE_MAP,
                                    .format = GL_RGBA32F,
                                    .size = {2, 2, 1},
                                    .label = "test.cube"});
    EXPECT_EQ(cube.layers(), 6);
    const std::vector<float> face(16, 3.0f);
    cube.uploadRegion({0, 0, 4}, {2, 2, 1}, GL_RGBA, GL_FLOAT, face.data());
    const std::vector<float> zero(16, 0.0f);
    cube.uploadRegion({0, 0, 0}, {2, 2, 1}, GL_RGBA, GL_FLOAT, zero.data());
    EXPECT_EQ(readTexture(cube, 0, 4).at(1, 1, 2), 3.0f);
    EXPECT_EQ(readTexture(cube, 0, 0).at(1, 1, 2), 0.0f);
}

TEST_F(GlRuntime, ReadbackOfAChosenChannelCountKeepsEveryPixelInItsPlace) {
    // 7 x 5: an odd height leaves a middle row that the in-place flip must not move; the values come
    // from the texel's GL position, so each read is checked against the upload, not the other read.
    const int w = 7, h = 5;
    std::vector<float> rgba, red;
    for (int glRow = 0; glRow < h; ++glRow)
        for (int x = 0; x < w; ++x) {
            rgba.insert(rgba.end(), {float(x), float(glRow), float(x * 100 + glRow), -1.0f});
            red.push_back(float(x + 10 * glRow));
        }
    Texture t = Texture::create({.format = GL_RGBA32F, .size = {w, h, 1}, .label = "test.rgba_as_rgb"});
    t.upload(GL_RGBA, GL_FLOAT, rgba.data());
    const Image rgb = readTexture(t, 0, -1, 3);
    ASSERT_EQ(rgb.channels, 3);
    ASSERT_EQ(rgb.pixels.size(), std::size_t(w * h * 3));
    Texture r = Texture::create({.format = GL_R32F, .size = {w, h, 1}, .label = "test.r_as_rgb"});
    r.upload(GL_RED, GL_FLOAT, red.data());
    const Image filled = readTexture(r, 0, -1, 3);  // green and blue come back 0
    ASSERT_EQ(filled.channels, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int glRow = h - 1 - y;
            EXPECT_EQ(rgb.at(x, y, 0), float(x));
            EXPECT_EQ(rgb.at(x, y, 1), float(glRow));
            EXPECT_EQ(rgb.at(x, y, 2), float(x * 100 + glRow));
            EXPECT_EQ(filled.at(x, y, 0), float(x + 10 * glRow));
            EXPECT_EQ(filled.at(x, y, 1), 0.0f);
            EXPECT_EQ(filled.at(x, y, 2), 0.0f);
        }
}

TEST_F(GlRuntime, BufferUploadAndDownload) {
    const std::vector<int> initial = {1, 2, 3, 4};
    Buffer b =
        Buffer::create({.bytes = 4 * sizeof(int), .data = initial.data(), .label = "test.buffer"});
    EXPECT_EQ(b.bytes(), 4 * sizeof(int));
    EXPECT_EQ(b.download<int>(), initial);
    const int patch[2] = {20, 30};
    b.upload(sizeof(int), sizeof patch, patch);
    EXPECT_EQ(b.download<int>(), (std::vector<int>{1, 20, 30, 4}));

    Buffer zeroed = Buffer::create({.bytes = 12, .label = "test.zeroed"});
    EXPECT_EQ(zeroed.download<int>(), (std::vector<int>{0, 0, 0}));
}

// ---- shaders ----

TEST_F(GlRuntime, ComputeShaderWithIncludesWritesExpectedValues) {
    Program p = Program::compile({.stages = {"test/fill.comp"}, .label = "test.fill"});
    EXPECT_EQ(p.workGroupSize(), glm::ivec3(4, 4, 1));
    const int w = 7, h = 5;
    Texture out =
        Texture::create({.format = GL_RGBA32F, .size = {w, h, 1}, .label = "test.fill_out"});
    out.bindImage(0, GL_WRITE_ONLY);
    p.use();
    const glm::ivec3 groups = groupCount({w, h, 1}, p.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    const Image img = readTexture(out);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int glY = h - 1 - y;
            // testValue in shaders/test/values.glsl: x + 100 y + 0.5
            const float expected = float(x) + 100.0f * float(glY) + 0.5f;
            EXPECT_EQ(img.at(x, y, 0), expected);
            EXPECT_EQ(img.at(x, y, 1), 2.0f * expected);
            EXPECT_EQ(img.at(x, y, 2), float(x));
            EXPECT_EQ(img.at(x, y, 3), float(glY));
        }
    }
}

TEST_F(GlRuntime, IncludesAreExpandedOnceWithLineMarkers) {
    const ShaderSource src = loadShaderSource("test/fill.comp");
    ASSERT_EQ(src.files.size(), 3u);
    EXPECT_EQ(src.files[0], "shaders/test/fill.comp");
    EXPECT_EQ(src.files[1], "shaders/test/values.glsl");
    EXPECT_EQ(src.files[2], "shaders/test/twice.glsl");
    // values.glsl is pulled in twice (directly and from twice.glsl) but expanded once.
    size_t count = 0;
    for (size_t at = src.text.find("float testValue("); at != std::string::npos;
         at = src.text.find("float testValue(", at + 1)) {
        ++count;
    }
    EXPECT_EQ(count, 1u);
    EXPECT_EQ(src.text.find("#include"), std::string::npos);
    EXPECT_NE(src.text.find("#line " + std::to_string(kShaderLineStride + 1) + " 1\n"),
              std::string::npos);
    EXPECT_EQ(src.text.rfind("#version 450 core", 0), 0u);  // #version stays the first line
}

TEST_F(GlRuntime, CompileErrorInIncludeNamesThatFileAndLine) {
    const int expectedLine = lineContaining("test/broken_include.glsl", "DELIBERATE ERROR");
    ASSERT_GT(expectedLine, 0);
    try {
        Program::compile({.stages = {"test/broken_in_include.comp"}, .label = "test.broken"});
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_EQ(e.file(), "shaders/test/broken_include.glsl");
        EXPECT_EQ(e.line(), expectedLine);
        const std::string prefix =
            "shaders/test/broken_include.glsl:" + std::to_string(expectedLine) + ": ";
        EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
    }
}

TEST_F(GlRuntime, CompileErrorAfterIncludeNamesTheMainFileLine) {
    const int expectedLine = lineContaining("test/broken_after_include.comp", "DELIBERATE ERROR");
    ASSERT_GT(expectedLine, 0);
    // With defines, extra lines are inserted after #version; numbering must still match the file.
    try {
        Program::compile({.stages = {"test/broken_after_include.comp"},
                          .defines = {{"A", "1"}, {"B", "2"}},
                          .label = "test.broken_after"});
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_EQ(e.file(), "shaders/test/broken_after_include.comp");
        EXPECT_EQ(e.line(), expectedLine) << e.what();
    }
}

TEST_F(GlRuntime, SyntaxErrorInIncludeNamesThatFile) {
    // Mesa reports a syntax error on the line after the one missing its semicolon.
    const int markedLine = lineContaining("test/broken_syntax.glsl", "DELIBERATE ERROR");
    ASSERT_GT(markedLine, 0);
    try {
        Program::compile({.stages = {"test/broken_syntax.comp"}, .label = "test.syntax"});
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_EQ(e.file(), "shaders/test/broken_syntax.glsl") << e.what();
        EXPECT_GE(e.line(), markedLine);
        EXPECT_LE(e.line(), markedLine + 1);
    }
}

TEST_F(GlRuntime, DriverLogFormatsAreMapped) {
    const std::vector<std::string> files = {"shaders/a.frag", "shaders/common/b.glsl"};
    std::string file;
    int line = 0;
    // Mesa, file index in the source-string number only.
    EXPECT_EQ(mapShaderLog("1:7(3): error: x", files, &file, &line),
              "shaders/common/b.glsl:7: error: x");
    // Mesa semantic error: source number lost (0), index encoded in the line number.
    EXPECT_EQ(mapShaderLog("0:" + std::to_string(kShaderLineStride + 9) + "(1): error: y", files,
                           &file, &line),
              "shaders/common/b.glsl:9: error: y");
    EXPECT_EQ(file, "shaders/common/b.glsl");
    EXPECT_EQ(line, 9);
    // NVIDIA style; a warning listed first still leaves the error as the first line and location.
    EXPECT_EQ(mapShaderLog("0(3) : warning C7050: w\n0(5) : error C1008: z", files, &file, &line),
              "shaders/a.frag:5: error C1008: z\nshaders/a.frag:3: warning C7050: w");
    EXPECT_EQ(line, 5);
}

TEST_F(GlRuntime, ShaderDirectoryFollowsTheEnvironment) {
    const char* saved = std::getenv("AIRLIGHT_SHADER_DIR");
    const std::string previous = saved ? saved : "";
    ::setenv("AIRLIGHT_SHADER_DIR", "/tmp/airlight_shader_dir_test", 1);
    EXPECT_EQ(shaderDirectory(), "/tmp/airlight_shader_dir_test");
    ::unsetenv("AIRLIGHT_SHADER_DIR");
    EXPECT_EQ(shaderDirectory(), std::string(VIZ_SOURCE_DIR) + "/shaders");
    if (saved)
        ::setenv("AIRLIGHT_SHADER_DIR", previous.c_str(), 1);
}

TEST_F(GlRuntime, MissingIncludeNamesTheIncludingLine) {
    const int expectedLine = lineContaining("test/missing_include.comp", "#include");
    try {
        loadShaderSource("test/missing_include.comp");
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_EQ(e.file(), "shaders/test/missing_include.comp");
        EXPECT_EQ(e.line(), expectedLine);
        EXPECT_NE(std::string(e.what()).find("test/does_not_exist.glsl"), std::string::npos);
    }
}

TEST_F(GlRuntime, DefinesReachTheShader) {
    Program p =
        Program::compile({.stages = {"test/defines.comp"},
                          .defines = {{"VALUE_INT", "-17"}, {"VALUE_FLOAT", "2.75"}, {"FLAG", ""}},
                          .label = "test.defines"});
    Buffer result = Buffer::create({.bytes = 3 * sizeof(int), .label = "test.defines_result"});
    result.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    p.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    int values[3] = {};
    result.download(0, sizeof values, values);
    float f = 0.0f;
    std::memcpy(&f, &values[1], sizeof f);
    EXPECT_EQ(values[0], -17);
    EXPECT_EQ(f, 2.75f);
    EXPECT_EQ(values[2], 1);
    // Without the define the shader's own #error fires.
    EXPECT_THROW(Program::compile({.stages = {"test/defines.comp"}}), ShaderError);
}

TEST_F(GlRuntime, BadDefinesAreReportedAsDefines) {
    try {
        loadShaderSource("test/defines.comp", {{"2D_MAPS", "1"}});
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("'2D_MAPS' is not a GLSL identifier"),
                  std::string::npos);
        EXPECT_EQ(e.file(), "shaders/test/defines.comp");
    }
    // Two different values for one macro: the preprocessor rejects the second define line.
    try {
        Program::compile(
            {.stages = {"test/defines.comp"},
             .defines = {{"VALUE_INT", "1"}, {"VALUE_FLOAT", "1.0"}, {"VALUE_INT", "2"}}});
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_EQ(e.file(), "<defines of shaders/test/defines.comp>") << e.what();
        EXPECT_EQ(e.line(), 3) << e.what();
    }
}

TEST_F(GlRuntime, DrawToFramebufferAndReadBackTopRowFirst) {
    const int w = 6, h = 4;
    Texture colour =
        Texture::create({.format = GL_RGBA32F, .size = {w, h, 1}, .label = "test.colour"});
    Framebuffer fb = Framebuffer::create("test.fb");
    fb.attachColour(0, colour);
    fb.checkComplete();
    VertexArray vao = VertexArray::create("test.empty_vao");
    Program p = Program::compile(
        {.stages = {"test/fullscreen.vert", "test/coords.frag"}, .label = "test.coords"});
    p.set("uTag", 0.625f);
    p.set("uDoesNotExist", 3.0f);  // ignored, as GL ignores location -1
    fb.bind();
    glViewport(0, 0, w, h);
    vao.bind();
    p.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    Framebuffer::bindDefault();
    const Image img = readTexture(colour);
    // gl_FragCoord.y is measured from the bottom: the image's top row holds the largest y.
    EXPECT_EQ(img.at(0, 0, 1), float(h) - 0.5f);
    EXPECT_EQ(img.at(0, h - 1, 1), 0.5f);
    EXPECT_EQ(img.at(w - 1, 0, 0), float(w) - 0.5f);
    EXPECT_EQ(img.at(2, 2, 2), 0.625f);
}

// ---- timing ----

TEST_F(GlRuntime, ClockMethodMatchesTheRenderer) {
    EXPECT_EQ(
        StageClock::methodName(StageClock::methodForRenderer("llvmpipe (LLVM 15.0.6, 256 bits)")),
        "glFinish+steady_clock");
    EXPECT_EQ(StageClock::methodName(StageClock::methodForRenderer("softpipe")),
              "glFinish+steady_clock");
    EXPECT_EQ(
        StageClock::methodName(StageClock::methodForRenderer("NVIDIA GeForce RTX 3060/PCIe/SSE2")),
        "GL_TIMESTAMP");
    if (context()->renderer().find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(StageClock::method(), "glFinish+steady_clock");
        StageClock clock;
        EXPECT_EQ(clock.clockMethod(), ClockMethod::FinishSteadyClock);
        clock.begin();
        EXPECT_GE(clock.endMilliseconds(), 0.0);
    }
}

// A stage that runs another technique inside it times its inner stages with clocks of their own (ivsv's
// gather runs vsv): the GPU clocks must nest without a GL error (two active GL_TIME_ELAPSED queries are
// GL_INVALID_OPERATION) and the outer interval must cover the inner one.
TEST_F(GlRuntime, GpuStageClocksNest) {
    while (glGetError() != GL_NO_ERROR) {
    }
    StageClock outer(ClockMethod::TimestampQuery), inner(ClockMethod::TimestampQuery);
    outer.begin();
    inner.begin();
    glFinish();
    const double innerMs = inner.endMilliseconds();
    const double outerMs = outer.endMilliseconds();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    EXPECT_GE(innerMs, 0.0);
    EXPECT_GE(outerMs, innerMs);
}

}  // namespace
}  // namespace viz::gl
