#include "progress_band.h"

#include <algorithm>

#include "core/text.h"

namespace airlight {

std::string renderingText(bool haveOutput, double lastRunSeconds) {
    if (!haveOutput) return "rendering...";
    return "rendering... (last run " + viz::format("%.1f s)", lastRunSeconds);
}

ProgressBand cpuProgressBand(const CpuProgress& progress) {
    ProgressBand band{"computing... " + passText(progress)};
    if (progress.pass > 0)
        band.text += " (" + std::to_string(progress.size.x) + "x" + std::to_string(progress.size.y) + ")  " +
                     viz::format("%.1f s", progress.elapsed);
    if (progress.estimate > 0.0 && progress.elapsed < 1.5 * progress.estimate) {
        band.fraction = float(std::min(0.99, progress.elapsed / progress.estimate));
        band.text += viz::format(" of ~%.1f s", progress.estimate);
    }
    return band;
}

}  // namespace airlight
