// The window fuzzed through `gui --script`: random key presses (every key of the key table, and the
// widgets' keys), clicks, drags, wheel turns, hovers and held keys at random points of the window, with a
// fixed seed, over every built-in scene and every stiff case. Whatever the actions do, the window must
// not abort, must raise no GL error, and its state (the session file it saves at the end, the sidecar of
// its last screenshot) must hold no NaN or infinity (JSON writes them as null).
//
// CI runs kActions actions per scene (27 scenes); AIRLIGHT_WINDOW_FUZZ_ACTIONS=N runs N per scene.
#include <cmath>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "scene/builtin_scenes.h"
#include "scene/stiff_scenes.h"

namespace viz::testing {
namespace {

constexpr int kActions = 40;

int actionsPerScene() {
    const char* n = std::getenv("AIRLIGHT_WINDOW_FUZZ_ACTIONS");
    return n ? std::max(1, std::atoi(n)) : kActions;
}

// Every other scene plays a --path loop of 4 frames when P is pressed (the camera turning, so that every
// scene can play it), whose reference frames render while a temporal view or the comparison grid shows;
// the rest play the light's orbit. AIRLIGHT_WINDOW_FUZZ_PATH=1 gives every scene the path.
bool playsAPath(unsigned seed) {
    const char* all = std::getenv("AIRLIGHT_WINDOW_FUZZ_PATH");
    return (all && std::string(all) == "1") || seed % 2 == 1;
}

std::vector<std::string> fuzzScenes() {
    std::vector<std::string> names = viz::scene::builtinSceneNames();
    for (const auto& c : viz::scene::stiffCases()) names.push_back("stiff/" + c.id);
    return names;
}

// Every key the window binds (app/input_table.cpp) except Escape (it quits), plus the widgets' keys.
const char* const kKeys[] = {"Tab", "Shift+Tab", "1",      "2",     "3",     "4",       "5",      "6",       "7",
                             "8",   "9",         "S",      "Shift+S", "D",   "Shift+D", "Home",   "End",     "[",
                             "]",   "V",         "Shift+V", ",",     ".",     "X",       "C",      "R",       "P",
                             "H",   "J",         "K",      "M",     "O",     "Shift+O", "N",      "Shift+N", "F",
                             "0",   "L",         "I",      "G",     "E",     "F12",     "F5",     "F9",      "Left",
                             "Right", "Up",      "Down",   "Enter", "Space", "PageUp",  "PageDown"};

std::string fuzzScript(unsigned seed, int actions, const std::string& statsPath) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto frac = [&] {
        std::ostringstream s;
        s.precision(3);
        s << std::fixed << unit(rng);
        return s.str();
    };
    const auto pick = [&](int n) { return int(rng() % unsigned(n)); };
    std::ostringstream out;
    out << "frames 2\n";
    for (int i = 0; i < actions; ++i) {
        const double r = unit(rng);
        if (r < 0.35) out << "key " << kKeys[pick(int(std::size(kKeys)))] << "\n";
        else if (r < 0.55) out << "click window " << frac() << " " << frac() << "\n";
        else if (r < 0.70) out << "drag window " << frac() << " " << frac() << " " << frac() << " " << frac() << "\n";
        else if (r < 0.80) out << "wheel window " << (pick(2) ? 1 : -1) * (1 + pick(3)) << "\n";
        else if (r < 0.88) out << "hover window " << frac() << " " << frac() << "\n";
        else if (r < 0.93) out << "hold " << "WASDQE"[pick(6)] << " " << 1 + pick(3) << "\n";
        else out << "frames " << 1 + pick(3) << "\n";
    }
    // Enter ends any text editing (a focused field takes every key), then F5 saves the session: the app state.
    out << "stats " << statsPath << "\nkey Enter\nframes 1\nkey F5\nframes 1\n";
    return out.str();
}

// Paths of JSON nulls and non-finite numbers under `j`, except under the keys listed in `mayBeNull`.
void findBadNumbers(const nlohmann::json& j, const std::string& at, const std::vector<std::string>& mayBeNull,
                    std::vector<std::string>& bad) {
    if (j.is_null()) bad.push_back(at + " is null");
    else if (j.is_number_float() && !std::isfinite(j.get<double>())) bad.push_back(at + " is not finite");
    else if (j.is_object()) {
        for (const auto& [key, value] : j.items())
            if (!(value.is_null() && std::find(mayBeNull.begin(), mayBeNull.end(), key) != mayBeNull.end()))
                findBadNumbers(value, at + "/" + key, mayBeNull, bad);
    } else if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i) findBadNumbers(j[i], at + "/" + std::to_string(i), mayBeNull, bad);
    }
}

class WindowFuzz : public WindowCliTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(WindowFuzz, RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState) {
    const std::string scene = GetParam();
    const unsigned seed = unsigned(std::hash<std::string>{}(scene) % 100000u) + 20261124u;
    const fs::path stats = path("stats.jsonl"), state = path("session.json");
    const fs::path script = writeText("fuzz.txt", fuzzScript(seed, actionsPerScene(), stats.string()));
    const ScopedCacheDir cache(path("cache"));  // the path's reference frames, and the difference views'
    const std::string motion = playsAPath(seed) ? " --path camera-orbit:20deg --path-frames 4" : "";
    const RunResult r = run("gui --scene " + scene + " --size 32x24" + motion + " --state " + state.string() +
                            " --export-dir " + path("exports").string() + " --script " + script.string() +
                            " --screenshot " + path("end.png").string());
    ASSERT_EQ(r.exitCode, 0) << scene << " (seed " << seed << "): " << r.err << "\nscript:\n" << readFile(script);
    EXPECT_EQ(r.err.find("check failed"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    const nlohmann::json line = nlohmann::json::parse(readFile(stats));
    EXPECT_EQ(line.at("gl_errors").get<long>(), 0) << scene;
    ASSERT_TRUE(fs::exists(state)) << scene << " (seed " << seed << "): F5 wrote no session file";
    std::vector<std::string> bad;
    findBadNumbers(nlohmann::json::parse(readFile(state)), "session", {}, bad);
    // The sidecar's null entries that mean "none": no cursor over a view, no linked pixel, no gizmo, a gizmo
    // handle that does not apply (a directional light has no position) or is behind the camera.
    findBadNumbers(nlohmann::json::parse(readFile(path("end.json"))), "sidecar", {"cursor", "linked_pixel", "gizmo", "position", "tip", "root", "position_grab", "tip_grab", "inspected"}, bad);
    for (const std::string& b : bad) ADD_FAILURE() << scene << " (seed " << seed << "): " << b;
    if (HasFailure()) {  // keep the script to replay: airlight gui --scene S --size 32x24 [PATH] --script FILE
        ADD_FAILURE() << "replay with:" << (motion.empty() ? " (no --path)" : motion);
        const fs::path kept = fs::current_path() / ("window_fuzz_" + std::to_string(seed) + ".txt");
        fs::copy_file(script, kept, fs::copy_options::overwrite_existing);
        ADD_FAILURE() << "script kept as " << kept;
    }
}

INSTANTIATE_TEST_SUITE_P(EveryScene, WindowFuzz, ::testing::ValuesIn(fuzzScenes()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             std::string name;
                             for (char c : param.param) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                             return name;
                         });

}  // namespace
}  // namespace viz::testing
