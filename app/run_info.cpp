#include "run_info.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "core/error.h"
#include "gl/context_info.h"
#include "gl/throughput_probe.h"

namespace airlight {

namespace {

// "A,B,,C" -> {"A", "B", "", "C"}.
std::vector<std::string> commaPieces(const std::string& text) {
    std::vector<std::string> pieces;
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        pieces.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return pieces;
}

// `items`, unless one is empty.
std::vector<std::string> withoutEmptyEntries(std::vector<std::string> items, const std::string& text,
                                             const std::string& flag) {
    for (const std::string& item : items)
        if (item.empty()) throw viz::InputError(flag + " '" + text + "' has an empty entry");
    return items;
}

}  // namespace

std::vector<std::string> splitList(const std::string& text, const std::string& flag) {
    return withoutEmptyEntries(commaPieces(text), text, flag);
}

std::vector<std::string> splitSceneList(const std::string& text, const std::string& flag) {
    const std::vector<std::string> pieces = commaPieces(text);
    std::vector<std::string> items;
    for (std::size_t i = 0; i < pieces.size();) {
        // The longest run of pieces from i that names a file; else piece i alone.
        std::size_t end = i + 1;
        std::string item = pieces[i], joined = pieces[i];
        for (std::size_t j = i + 1; j < pieces.size(); ++j) {
            joined += "," + pieces[j];
            std::error_code ec;
            if (std::filesystem::is_regular_file(joined, ec)) item = joined, end = j + 1;
        }
        items.push_back(item);
        i = end;
    }
    return withoutEmptyEntries(std::move(items), text, flag);
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string utcNow() {
    const std::time_t now = std::time(nullptr);
    char buffer[32];
    std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    return buffer;
}

std::string machineDescription() {
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    std::string cpu = "unknown CPU";
    std::ifstream info("/proc/cpuinfo");
    for (std::string line; std::getline(info, line);)
        if (line.rfind("model name", 0) == 0) {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    return std::string(host) + ", " + cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " threads";
}

std::string rendererDescription() {
    const viz::gl::ContextInfo info = viz::gl::contextInfo();
    return info.renderer + ", OpenGL " + info.version;
}

RendererArithmetic measureRendererArithmetic() {
    const viz::gl::ArithmeticRatio ratio = viz::gl::measureArithmeticRatio();
    RendererArithmetic r{ratio.fragmentOverCompute, viz::gl::describeArithmeticRatio(ratio)};
    if (ratio.handicapsFragments()) std::fprintf(stderr, "note: %s\n", r.line.c_str());
    return r;
}

std::string fileStem(const std::string& text) {
    std::string out;
    for (char c : text) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
    return out;
}

TimedRuns timeRuns(viz::Technique& technique, const viz::FrameInput& input, int runs) {
    TimedRuns timed;
    timed.last = technique.run(input);  // warm-up
    std::vector<double> totals, walls;
    int compiled = 0;  // shader programs compiled after the warm-up: none, for a technique that keeps them
    std::vector<std::string> order;
    std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> stages;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        timed.last = technique.run(input);
        walls.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        totals.push_back(timed.last.timing.totalMilliseconds());
        compiled += timed.last.timing.programsCompiled();
        for (const viz::StageTiming& s : timed.last.timing.stages) {
            auto [it, added] = stages.try_emplace(s.stage);
            if (added) order.push_back(s.stage);
            it->second.first.push_back(s.milliseconds);
            it->second.second.push_back(s.wallMilliseconds >= 0.0 ? s.wallMilliseconds : s.milliseconds);
        }
    }
    for (const std::string& id : order)
        timed.stages.push_back({id, median(stages[id].first), median(stages[id].second), viz::report::spreadOf(stages[id].first)});
    if (compiled > 0)
        std::fprintf(stderr, "note: %s compiled %d shader programs in its %d timed runs after the warm-up: its times "
                             "include compiling\n", technique.id().c_str(), compiled, runs);
    timed.totalMilliseconds = median(totals);
    timed.wallMilliseconds = median(walls);
    timed.totalSpread = viz::report::spreadOf(totals);
    timed.wallSpread = viz::report::spreadOf(walls);
    return timed;
}

Progress::Progress(int total) : mTotal(total), mTty(isatty(STDERR_FILENO)) {}

void Progress::show(int done, const std::string& what) {
    constexpr int kWidth = 24;
    const int filled = mTotal > 0 ? std::clamp(done * kWidth / mTotal, 0, kWidth) : kWidth;
    std::string bar(std::size_t(filled), '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "%s[%s] %d/%d %s%s", mTty ? "\r\033[K" : "", bar.c_str(), done, mTotal, what.c_str(),
                 mTty ? "" : "\n");
    std::fflush(stderr);
}

void Progress::finish() {
    if (mTty) std::fputc('\n', stderr);
}

}  // namespace airlight
