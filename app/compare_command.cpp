#include "compare_command.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "core/image_io.h"
#include "report/error_images.h"
#include "report/error_metrics.h"

namespace airlight {

namespace {

constexpr const char* kUsage =
    "usage: airlight compare TEST REFERENCE [--heatmap OUT.png|OUT.exr]\n\n"
    "Prints the error of TEST against REFERENCE (images of the same size and channels): relative L2,\n"
    "RMSE, max absolute (and where), the 99.9th-percentile relative error, PSNR on the report's tone map,\n"
    "and the NaN, Inf and negative pixel counts. --heatmap writes sum_c |TEST - REFERENCE| as a heat map\n"
    "(scaled so the 99.5th percentile of the reference maps to the top of the colour map).\n";

// The pixel with the largest |test - ref| over its channels (the first one when tied).
std::pair<int, int> worstPixel(const viz::Image& test, const viz::Image& ref) {
    double worst = -1.0;
    std::pair<int, int> at{0, 0};
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x)
            for (int c = 0; c < ref.channels; ++c) {
                const std::size_t i = (std::size_t(y) * std::size_t(ref.width) + std::size_t(x)) * std::size_t(ref.channels) + std::size_t(c);
                const double d = std::fabs(double(test.pixels[i]) - double(ref.pixels[i]));
                if (d > worst) {
                    worst = d;
                    at = {x, y};
                }
            }
    return at;
}

}  // namespace

int runCompare(Args& args) {
    if (args.empty() || isHelpFlag(args.peek())) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    std::string testPath, refPath, heatmap;
    while (!args.empty()) {
        const std::string word = args.take();
        if (word == "--heatmap") heatmap = args.next(word);
        else if (!word.empty() && word[0] == '-') throw viz::InputError("unknown option '" + word + "' for 'compare'");
        else if (testPath.empty()) testPath = word;
        else if (refPath.empty()) refPath = word;
        else throw viz::InputError("compare takes two images, got a third: '" + word + "'");
    }
    if (refPath.empty()) throw viz::InputError("compare needs two images: airlight compare TEST REFERENCE");
    const viz::Image test = viz::readImage(testPath), ref = viz::readImage(refPath);
    if (test.width != ref.width || test.height != ref.height || test.channels != ref.channels)
        throw viz::InputError("compare: '" + testPath + "' is " + std::to_string(test.width) + "x" +
                              std::to_string(test.height) + "x" + std::to_string(test.channels) + " but '" + refPath +
                              "' is " + std::to_string(ref.width) + "x" + std::to_string(ref.height) + "x" +
                              std::to_string(ref.channels) + " (width x height x channels)");
    const viz::report::ErrorMetrics m = viz::report::compareImages(test, ref);
    const auto [wx, wy] = worstPixel(test, ref);
    std::printf("relative L2 %.6g  RMSE %.6g  max abs %.6g at (%d, %d)  p99.9 relative %.6g  PSNR %.2f dB  "
                "NaN %zu  Inf %zu  negative %zu  (%zu pixels)\n",
                m.relativeL2, m.rmse, m.maxAbsolute, wx, wy, m.relativeP999, m.psnr, m.nanPixels, m.infPixels,
                m.negativePixels, m.pixels);
    if (!heatmap.empty()) {
        const float scale = viz::report::exposureFor(ref);
        viz::writeImage(viz::report::errorHeatMap(test, ref, scale), heatmap);
        std::printf("wrote %s\n", heatmap.c_str());
    }
    return 0;
}

}  // namespace airlight
