// The OpenImageIO module (core/oiio_module.h): PNG and EXR never need it; another format does, and it
// is loaded for it; a program that cannot load it says so in one line and still reads PNG and EXR.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cli/cli_fixture.h"

namespace viz::testing {
namespace {

class ImageModuleTest : public CliTest {
protected:
    // A binary Netpbm grey image (P5), written here byte by byte: a format stb_image is not built for.
    fs::path writePgm(const std::string& name, unsigned char a, unsigned char b) const {
        const fs::path p = path(name);
        std::ofstream out(p, std::ios::binary);
        out << "P5\n2 1\n255\n" << a << b;
        return p;
    }
};

TEST_F(ImageModuleTest, CompareReadsANetpbmImageThroughTheModule) {
    const fs::path a = writePgm("a.pgm", 16, 128), b = writePgm("b.pgm", 16, 64);
    const RunResult same = run("compare " + a.string() + " " + a.string());
    ASSERT_EQ(same.exitCode, 0) << same.err;
    EXPECT_NE(same.out.find("relative L2 0 "), std::string::npos) << same.out;
    EXPECT_NE(same.out.find("(2 pixels)"), std::string::npos) << same.out;
    // Against b: sqrt((128 - 64)^2 / (16^2 + 64^2)) = 0.970 (the values' scale cancels).
    const RunResult differ = run("compare " + a.string() + " " + b.string());
    ASSERT_EQ(differ.exitCode, 0) << differ.err;
    EXPECT_NE(differ.out.find("relative L2 0.970"), std::string::npos) << differ.out;
}

TEST_F(ImageModuleTest, WithoutTheModuleOtherFormatsAreAOneLineErrorAndPngStillReads) {
    const fs::path pgm = writePgm("a.pgm", 16, 128);
    const fs::path png = path("a.png");
    ASSERT_EQ(run("render --scene grate --technique raymarch --size 8x6 --quiet --out " + png.string()).exitCode, 0);
    const ScopedEnv missing("AIRLIGHT_OIIO_MODULE", "/nonexistent/libairlight_oiio.so");
    expectUserError(run("compare " + pgm.string() + " " + pgm.string()), "/nonexistent/libairlight_oiio.so");
    const RunResult r = run("compare " + png.string() + " " + png.string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    expectUserError(run("animate --scene grate --technique raymarch --size 8x6 --frames 2 --path camera-orbit:10deg --out " +
                        path("a.gif").string()),
                    "no animated GIF without OpenImageIO");
    EXPECT_FALSE(fs::exists(path("a.gif")));
}

}  // namespace
}  // namespace viz::testing
