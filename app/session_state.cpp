#include "session_state.h"

#include "core/json_check.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "cli_args.h"
#include "techniques/registry.h"
#include "view_layout.h"

namespace airlight {

namespace {

using nlohmann::json;

json vec3(glm::dvec3 v) { return json::array({v.x, v.y, v.z}); }

// The named values of a technique's parameter (ParamInfo::choices); empty for a plain number or an
// unknown technique or parameter.
std::vector<std::string> choicesOf(const std::string& technique, const std::string& name) {
    const std::vector<std::string> ids = viz::techniqueIds();
    if (std::find(ids.begin(), ids.end(), technique) == ids.end()) return {};
    const std::unique_ptr<viz::Technique> t = viz::makeTechnique(technique);  // alive while its params are read
    for (const viz::ParamInfo& p : t->params())
        if (p.name == name) return p.choices;
    return {};
}

// A setting as the file writes it: a named value by its name, anything else as a number.
json settingJson(const std::string& technique, const std::string& name, double value) {
    const std::vector<std::string> choices = choicesOf(technique, name);
    if (value >= 0.0 && value == std::floor(value) && value < double(choices.size())) return choices[std::size_t(value)];
    return value;
}

// A setting as read: a number, or one of the parameter's names.
double settingValue(const std::string& technique, const std::string& name, const json& value) {
    if (!value.is_string()) return value.get<double>();
    const std::vector<std::string> choices = choicesOf(technique, name);
    for (std::size_t i = 0; i < choices.size(); ++i)
        if (choices[i] == value.get<std::string>()) return double(i);
    std::string known;
    for (const std::string& c : choices) known += (known.empty() ? "" : ", ") + c;
    throw std::runtime_error("setting " + technique + "." + name + " is '" + value.get<std::string>() + "'" +
                             (known.empty() ? std::string(" (it takes a number)") : " (known: " + known + ")"));
}

// Reads a finite 3-vector or throws with the key's name.
glm::dvec3 readVec3(const json& j, const char* key) {
    const json& a = j.at(key);
    if (!a.is_array() || a.size() != 3) throw std::runtime_error(std::string(key) + " is not a 3-vector");
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) {
        v[i] = a[std::size_t(i)].get<double>();
        if (!std::isfinite(v[i])) throw std::runtime_error(std::string(key) + " is not finite");
    }
    return v;
}

double readNumber(const json& j, const char* key, double lo, double hi) {
    const double v = j.at(key).get<double>();
    if (!std::isfinite(v) || v < lo || v > hi)
        throw std::runtime_error(std::string(key) + " is out of range");
    return v;
}

}  // namespace

std::vector<SessionState::LightPlacement> lightPlacements(const viz::scene::Scene& scene) {
    std::vector<SessionState::LightPlacement> out;
    for (const auto& l : scene.lights) out.push_back({l.position, l.direction, l.intensity});
    return out;
}

bool applyLightPlacements(const std::vector<SessionState::LightPlacement>& placements, viz::scene::Scene& scene) {
    if (placements.size() != scene.lights.size()) return false;
    for (std::size_t i = 0; i < placements.size(); ++i) {
        scene.lights[i].position = placements[i].position;
        scene.lights[i].direction = placements[i].direction;
        scene.lights[i].intensity = placements[i].intensity;
    }
    return true;
}

std::string sessionToJson(const SessionState& s) {
    json j;
    j["version"] = SessionState::kVersion;
    j["scene"] = s.scene;
    j["technique"] = s.technique;
    j["size"] = {s.width, s.height};
    if (s.camera) {
        const auto& c = *s.camera;
        j["camera"] = {{"position", vec3(c.position)}, {"forward", vec3(c.forward)}, {"up", vec3(c.up)},
                       {"yfov", c.yfov},           {"znear", c.znear},           {"zfar", c.zfar},
                       {"target", vec3(s.orbitTarget)}};
    }
    if (s.medium) j["medium"] = {{"sigma_s", s.medium->sigma_s}, {"sigma_a", s.medium->sigma_a}, {"g", s.medium->g}};
    if (!s.lights.empty()) {
        json lights = json::array();
        for (const auto& l : s.lights)
            lights.push_back({{"position", vec3(l.position)}, {"direction", vec3(l.direction)}, {"intensity", l.intensity}});
        j["lights"] = lights;
    }
    json settings = json::object();
    for (const auto& [technique, values] : s.settings)
        for (const auto& [name, value] : values) settings[technique][name] = settingJson(technique, name, value);
    j["settings"] = settings;
    j["view"] = s.view;
    j["view_zoom"] = s.viewZoom;
    j["view_center"] = {s.viewCenter.x, s.viewCenter.y};
    j["exposure"] = s.exposure;
    j["exposure_set"] = s.exposureSet;
    if (!s.lesson.empty()) j["lesson"] = {{"path", s.lesson}, {"step", s.lessonStep}, {"try_it", s.lessonTryIt}};
    if (!s.layout.empty()) {
        json views = json::array();
        for (const auto& v : s.gridViews)
            views.push_back({{"id", v.id}, {"content", v.content}, {"layer", v.layer}, {"zoom", v.zoom},
                             {"center", {v.center.x, v.center.y}}, {"channel", v.channel}, {"range", v.range},
                             {"manual", {v.manualMin, v.manualMax}}, {"log", v.logScale}, {"colour_map", v.colourMap},
                             {"mark_negative", v.markNegative}, {"difference", v.difference},
                             {"against", v.against}, {"strip_open", v.stripOpen}});
        j["view_grid"] = {{"layout", s.layout}, {"focused", s.focusedView}, {"maximised", s.maximisedView},
                          {"views", views}};
    }
    return j.dump(2) + "\n";
}

SessionState sessionFromJson(const std::string& text, std::string& problem) {
    problem.clear();
    SessionState s;
    try {
        // The file is user input: depth-checked before nlohmann builds it.
        if (const std::string bad = viz::jsonProblem(text, 32); !bad.empty()) throw std::runtime_error(bad);
        const json j = json::parse(text);
        if (!j.is_object()) throw std::runtime_error("not a JSON object");
        if (j.at("version").get<int>() != SessionState::kVersion)
            throw std::runtime_error("version " + j.at("version").dump() + " is not " +
                                     std::to_string(SessionState::kVersion));
        s.scene = j.at("scene").get<std::string>();
        s.technique = j.at("technique").get<std::string>();
        const json& size = j.at("size");
        if (!size.is_array() || size.size() != 2) throw std::runtime_error("size is not [width, height]");
        s.width = size[0].get<int>();
        s.height = size[1].get<int>();
        if (s.width < 1 || s.height < 1 || s.width > kMaxImageSide || s.height > kMaxImageSide)
            throw std::runtime_error("size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                                     " is out of range (each side 1.." + std::to_string(kMaxImageSide) + ")");
        if (j.contains("camera")) {
            const json& c = j.at("camera");
            viz::scene::Camera cam;
            cam.position = readVec3(c, "position");
            cam.forward = readVec3(c, "forward");
            cam.up = readVec3(c, "up");
            if (glm::length(cam.forward) < 1e-9 || glm::length(cam.up) < 1e-9)
                throw std::runtime_error("camera direction is zero");
            cam.forward = glm::normalize(cam.forward);
            cam.up = glm::normalize(cam.up - glm::dot(cam.up, cam.forward) * cam.forward);
            cam.yfov = readNumber(c, "yfov", 1e-3, 3.1);
            cam.znear = readNumber(c, "znear", 1e-9, 1e12);
            cam.zfar = readNumber(c, "zfar", cam.znear, 1e15);
            s.camera = cam;
            s.orbitTarget = readVec3(c, "target");
        }
        if (j.contains("medium")) {
            const json& m = j.at("medium");
            s.medium = viz::scene::Medium{readNumber(m, "sigma_s", 0, 1e6), readNumber(m, "sigma_a", 0, 1e6),
                                          readNumber(m, "g", -0.999, 0.999)};
        }
        if (j.contains("lights")) {  // optional: files written before the light gizmo have none
            const json& lights = j.at("lights");
            if (!lights.is_array()) throw std::runtime_error("lights is not an array");
            for (const json& l : lights) {
                SessionState::LightPlacement p;
                p.position = readVec3(l, "position");
                if (glm::any(glm::greaterThan(glm::abs(p.position), glm::dvec3(1e15))))
                    throw std::runtime_error("a light's position lies beyond 1e15 from the origin");
                p.direction = readVec3(l, "direction");
                if (glm::length(p.direction) < 1e-9) throw std::runtime_error("a light's direction is zero");
                p.direction = glm::normalize(p.direction);
                p.intensity = readNumber(l, "intensity", 0.0, 1e20);
                s.lights.push_back(p);
            }
        }
        for (const auto& [technique, values] : j.at("settings").items())
            for (const auto& [name, value] : values.items()) {
                const double v = settingValue(technique, name, value);
                if (!std::isfinite(v)) throw std::runtime_error("setting " + technique + "." + name + " is not finite");
                s.settings[technique][name] = v;
            }
        s.view = j.at("view").get<std::string>();
        if (j.contains("view_zoom")) {
            s.viewZoom = readNumber(j, "view_zoom", 1.0, 4096.0);
            const json& c = j.at("view_center");
            if (!c.is_array() || c.size() != 2) throw std::runtime_error("view_center is not [u, v]");
            s.viewCenter = {c[0].get<double>(), c[1].get<double>()};
            if (!std::isfinite(s.viewCenter.x) || !std::isfinite(s.viewCenter.y))
                throw std::runtime_error("view_center is not finite");
        }
        s.exposure = float(readNumber(j, "exposure", -40, 40));
        s.exposureSet = j.at("exposure_set").get<bool>();
        if (j.contains("lesson")) {  // optional: files written before the lesson player have none
            const json& l = j.at("lesson");
            s.lesson = l.at("path").get<std::string>();
            s.lessonStep = l.at("step").get<int>();
            if (s.lesson.empty()) throw std::runtime_error("lesson path is empty");
            if (s.lessonStep < 0 || s.lessonStep > 100000) throw std::runtime_error("lesson step is out of range");
            s.lessonTryIt = l.at("try_it").get<bool>();
        }
        if (j.contains("view_grid")) {
            const json& g = j.at("view_grid");
            s.layout = g.at("layout").get<std::string>();
            const ViewLayout layout = ViewLayout::fromText(s.layout);  // throws naming the problem
            s.focusedView = g.at("focused").get<int>();
            s.maximisedView = g.at("maximised").get<int>();
            for (const json& v : g.at("views")) {
                SessionState::GridView e;
                e.id = v.at("id").get<int>();
                if (!layout.contains(e.id)) throw std::runtime_error("view_grid: view " + std::to_string(e.id) + " is not in the layout");
                e.content = v.at("content").get<std::string>();
                e.layer = v.at("layer").get<int>();
                e.zoom = readNumber(v, "zoom", 1.0, 4096.0);
                const json& c = v.at("center");
                if (!c.is_array() || c.size() != 2) throw std::runtime_error("view_grid: center is not [u, v]");
                e.center = {c[0].get<double>(), c[1].get<double>()};
                if (!std::isfinite(e.center.x) || !std::isfinite(e.center.y))
                    throw std::runtime_error("view_grid: center is not finite");
                e.channel = int(readNumber(v, "channel", 0, 5));
                e.range = int(readNumber(v, "range", 0, 3));
                e.colourMap = int(readNumber(v, "colour_map", 0, 6));
                e.difference = int(readNumber(v, "difference", 0, 3));
                const json& m = v.at("manual");
                if (!m.is_array() || m.size() != 2) throw std::runtime_error("view_grid: manual is not [min, max]");
                e.manualMin = m[0].get<float>();
                e.manualMax = m[1].get<float>();
                if (!std::isfinite(e.manualMin) || !std::isfinite(e.manualMax))
                    throw std::runtime_error("view_grid: manual range is not finite");
                e.logScale = v.at("log").get<bool>();
                e.markNegative = int(readNumber(v, "mark_negative", -1, 1));
                e.against = v.at("against").get<std::string>();
                e.stripOpen = v.at("strip_open").get<bool>();
                s.gridViews.push_back(e);
            }
        }
    } catch (const std::exception& e) {
        // nlohmann's messages start with "[json.exception.type_error.302] ...": keep the readable part.
        std::string what = e.what();
        if (what.rfind("[json.exception.", 0) == 0 && what.find("] ") != std::string::npos)
            what = what.substr(what.find("] ") + 2);
        problem = what;
        return SessionState{};
    }
    return s;
}

std::string defaultSessionPath() {
    namespace fs = std::filesystem;
    if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state)
        return (fs::path(state) / "airlight" / "session.json").string();
    const char* home = std::getenv("HOME");
    return (fs::path(home && *home ? home : ".") / ".local" / "state" / "airlight" / "session.json").string();
}

SessionRead readSession(const std::string& path) {
    SessionRead r;
    std::error_code statusError;  // a path that cannot be looked at reads as one that does not exist
    const std::filesystem::file_status status = std::filesystem::status(path, statusError);
    if (!std::filesystem::exists(status)) {
        // A new session: not a problem with the file, but worth a word on where the state will go.
        r.problem = "state file '" + path + "' does not exist yet";
        return r;
    }
    r.file = SessionRead::File::Broken;
    if (!std::filesystem::is_regular_file(status)) {
        // A folder, a FIFO or a device: never read (a FIFO would block).
        r.problem = "state file '" + path + "' is not a regular file";
        return r;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        r.problem = "state file '" + path + "' cannot be read";
        return r;
    }
    std::stringstream text;
    text << in.rdbuf();
    std::string problem;
    r.state = sessionFromJson(text.str(), problem);
    if (!problem.empty()) {
        r.problem = "state file '" + path + "': " + problem;
        return r;
    }
    r.file = SessionRead::File::Loaded;
    return r;
}

SessionState loadSession(const std::string& path, std::string& problem) {
    SessionRead r = readSession(path);
    problem = r.problem;
    if (r.file == SessionRead::File::Missing) problem += "; nothing loaded (F5 or closing the window saves it)";
    if (r.file != SessionRead::File::Broken) return std::move(r.state);
    problem += "; nothing loaded";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return std::move(r.state);  // a folder is never moved
    // Never lose a hand-edited file: it is moved aside, to a name that holds nothing yet, before the
    // window saves over its name.
    std::string aside = path + ".broken";
    for (int n = 2; std::filesystem::exists(std::filesystem::symlink_status(aside, ec)) && n <= 1000; ++n)
        aside = path + ".broken." + std::to_string(n);
    if (std::filesystem::exists(std::filesystem::symlink_status(aside, ec))) {
        problem += " (not moved aside: " + path + ".broken to .broken.1000 all exist)";
        return std::move(r.state);
    }
    std::filesystem::rename(path, aside, ec);
    problem += ec ? " (the file could not be moved aside: " + ec.message() + ")" : "; the file was moved to '" + aside + "'";
    return std::move(r.state);
}

SessionRead loadNamedSession(const std::string& path) {
    SessionRead r = readSession(path);
    if (r.file == SessionRead::File::Broken)
        throw viz::InputError(r.problem + "; not an Airlight session: fix it, or name a file that does not exist "
                                          "yet to start a new session there (the file was left as it is)");
    if (r.file == SessionRead::File::Missing) r.problem += "; a new session (F5 or closing the window saves it)";
    return r;
}

void saveSession(const std::string& path, const SessionState& state) {
    const std::filesystem::path target(path);
    std::error_code ec;
    if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), ec);
    const std::string error = viz::writeFileAtomically(target, sessionToJson(state));
    if (!error.empty()) throw viz::InputError("cannot save the session to '" + path + "': " + error);
}

}  // namespace airlight
