// Per-stage timing records. On llvmpipe GL timer queries do not measure the work, so GPU stages there
// are bracketed by glFinish and a steady clock; the record says which clock was used.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace viz {

// Work counts of a stage in a counting run (gl/work_counters.h), indexed by the kWork* constants of
// shaders/common/host_device.glsl; empty outside counting runs.
using WorkCounts = std::vector<std::uint64_t>;

struct StageTiming {
    std::string stage;
    double milliseconds = 0.0;  // by the record's clock (GPU time where GL timer queries are trusted)
    // Wall time on the CPU from the stage's start until its time was known (gl::StageClock: the GPU's
    // result waited for), so CPU work inside the stage shows where the GPU time does not; -1 where it is
    // not measured apart (CPU stages, whose milliseconds are wall time already).
    double wallMilliseconds = -1.0;
    WorkCounts work{};  // counting runs only
    // Shader programs compiled inside the stage (gl::StageClock; first use of a program or permutation):
    // its time includes compiling them, so it is no warm figure. 0 for CPU stages.
    int programsCompiled = 0;
};

struct Timing {
    std::string clock;  // "steady_clock" (CPU), "glFinish+steady_clock", "GL_TIMESTAMP"
    std::vector<StageTiming> stages;
    double totalMilliseconds() const {
        double t = 0.0;
        for (const auto& s : stages) t += s.milliseconds;
        return t;
    }
    // Shader programs compiled in the run (StageTiming::programsCompiled summed): not 0, and its times
    // include first-use compiles.
    int programsCompiled() const {
        int n = 0;
        for (const auto& s : stages) n += s.programsCompiled;
        return n;
    }
    // A counting run's work summed over the stages (empty outside counting runs).
    WorkCounts totalWork() const {
        WorkCounts total;
        for (const auto& s : stages) {
            if (total.size() < s.work.size()) total.resize(s.work.size(), 0);
            for (std::size_t c = 0; c < s.work.size(); ++c) total[c] += s.work[c];
        }
        return total;
    }
};

// The clock a stage runner times its stages with: gl::StageClock for GPU stages, CpuStageClock below for
// CPU ones. begin() starts a stage; end(stage) is its record.
class StageTimer {
public:
    virtual ~StageTimer() = default;
    virtual void begin() = 0;
    virtual StageTiming end(const std::string& stage) = 0;
    virtual std::string name() const = 0;  // Timing::clock
};

// Times CPU work with a steady clock.
class CpuStopwatch {
public:
    CpuStopwatch() : mStart(std::chrono::steady_clock::now()) {}
    double elapsedMilliseconds() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mStart).count();
    }

private:
    std::chrono::steady_clock::time_point mStart;
};

// CPU stages: wall time by the steady clock ("steady_clock").
class CpuStageClock final : public StageTimer {
public:
    void begin() override { mWatch = CpuStopwatch(); }
    StageTiming end(const std::string& stage) override { return {stage, mWatch.elapsedMilliseconds()}; }
    std::string name() const override { return "steady_clock"; }

private:
    CpuStopwatch mWatch;
};

}  // namespace viz
