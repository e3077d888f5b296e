// Reading a motion path: the declarative text and the keyframe file (motion_path.h describes both).
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/json_check.h"
#include "scene/motion_path.h"

namespace viz::scene {

namespace {

constexpr const char* kKnown = "camera-orbit, camera-dolly, light-orbit, light-sweep, or a .json keyframe file";
constexpr double kMaxTurns = 100.0;             // |angle| up to 100 full turns
constexpr std::size_t kMaxKeyframes = 100000;
constexpr std::uintmax_t kMaxFileBytes = 64u << 20;

// A finite number filling `text` exactly, or nullopt.
std::optional<double> number(const std::string& text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

double angle(const std::string& value, const std::string& name, const std::string& whole) {
    const std::string bad = "path '" + whole + "': " + name + " takes an angle such as " + name + ":30deg or " +
                            name + ":0.5rad, got '" + value + "'";
    double radians = 0.0;
    if (value.ends_with("deg")) {
        const auto v = number(value.substr(0, value.size() - 3));
        if (!v) throw InputError(bad);
        radians = *v * std::numbers::pi / 180.0;
    } else if (value.ends_with("rad")) {
        const auto v = number(value.substr(0, value.size() - 3));
        if (!v) throw InputError(bad);
        radians = *v;
    } else {
        throw InputError(bad);
    }
    if (std::abs(radians) > kMaxTurns * 2.0 * std::numbers::pi)
        throw InputError("path '" + whole + "': " + name + " angle '" + value + "' is more than 100 turns");
    return radians;
}

Motion motion(const std::string& item, const std::string& whole) {
    if (item.empty()) throw InputError("path '" + whole + "': an empty motion (known: " + kKnown + ")");
    const std::size_t colon = item.find(':');
    const std::string name = item.substr(0, colon);
    const std::optional<std::string> value =
        colon == std::string::npos ? std::nullopt : std::optional<std::string>(item.substr(colon + 1));
    Motion m;
    if (name == "camera-orbit" || name == "light-orbit") {
        m.kind = name == "camera-orbit" ? MotionKind::CameraOrbit : MotionKind::LightOrbit;
        m.amount = value ? angle(*value, name, whole) : 2.0 * std::numbers::pi;
    } else if (name == "light-sweep") {
        if (!value) throw InputError("path '" + whole + "': light-sweep needs an angle, e.g. light-sweep:20deg");
        m.kind = MotionKind::LightSweep;
        m.amount = angle(*value, name, whole);
    } else if (name == "camera-dolly") {
        const std::string example = "e.g. camera-dolly:2 (scene units) or camera-dolly:25% (of the distance to the "
                                    "orbit target)";
        if (!value) throw InputError("path '" + whole + "': camera-dolly needs a distance, " + example);
        m.kind = MotionKind::CameraDolly;
        m.percent = value->ends_with("%");
        const auto v = number(m.percent ? value->substr(0, value->size() - 1) : *value);
        if (!v) throw InputError("path '" + whole + "': camera-dolly distance '" + *value + "' is not a number, " + example);
        m.amount = m.percent ? *v / 100.0 : *v;
    } else {
        throw InputError("path '" + whole + "': unknown motion '" + name + "' (known: " + kKnown + ")");
    }
    return m;
}

// ---- keyframes ----

std::string where(const std::string& source, std::size_t key) {
    return "keyframe file '" + source + "': keyframe " + std::to_string(key + 1);
}

void onlyKeys(const nlohmann::json& object, const std::set<std::string>& allowed, const std::string& context) {
    for (auto it = object.begin(); it != object.end(); ++it)
        if (!allowed.count(it.key())) {
            std::string known;
            for (const std::string& k : allowed) known += (known.empty() ? "" : ", ") + k;
            throw InputError(context + ": unknown member '" + it.key() + "' (known: " + known + ")");
        }
}

std::optional<glm::dvec3> vec3(const nlohmann::json& object, const char* name, const std::string& context) {
    if (!object.contains(name)) return std::nullopt;
    const nlohmann::json& a = object.at(name);
    if (!a.is_array() || a.size() != 3 || !std::all_of(a.begin(), a.end(), [](const auto& v) { return v.is_number(); }))
        throw InputError(context + ": '" + name + "' must be an array of 3 numbers");
    const glm::dvec3 v(a[0].get<double>(), a[1].get<double>(), a[2].get<double>());
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw InputError(context + ": '" + name + "' must be finite");
    return v;
}

Keyframe keyframe(const nlohmann::json& k, const std::string& context) {
    if (!k.is_object()) throw InputError(context + " must be an object");
    onlyKeys(k, {"t", "camera", "light"}, context);
    Keyframe key;
    if (!k.contains("t") || !k.at("t").is_number()) throw InputError(context + " needs a number 't'");
    key.time = k.at("t").get<double>();
    if (!std::isfinite(key.time)) throw InputError(context + ": 't' must be finite");
    if (k.contains("camera")) {
        const nlohmann::json& c = k.at("camera");
        const std::string at = context + " camera";
        if (!c.is_object()) throw InputError(at + " must be an object");
        onlyKeys(c, {"position", "target", "up"}, at);
        key.cameraPosition = vec3(c, "position", at);
        key.cameraTarget = vec3(c, "target", at);
        key.cameraUp = vec3(c, "up", at);
        if (!key.cameraPosition || !key.cameraTarget) throw InputError(at + " needs 'position' and 'target'");
        if (*key.cameraPosition == *key.cameraTarget) throw InputError(at + ": 'target' is at 'position'");
        if (key.cameraUp && glm::length(*key.cameraUp) == 0.0) throw InputError(at + ": 'up' is zero");
    }
    if (k.contains("light")) {
        const nlohmann::json& l = k.at("light");
        const std::string at = context + " light";
        if (!l.is_object()) throw InputError(at + " must be an object");
        onlyKeys(l, {"position", "direction"}, at);
        key.lightPosition = vec3(l, "position", at);
        key.lightDirection = vec3(l, "direction", at);
        if (!key.lightPosition && !key.lightDirection) throw InputError(at + " needs 'position' or 'direction'");
        if (key.lightDirection && glm::length(*key.lightDirection) == 0.0) throw InputError(at + ": 'direction' is zero");
    }
    return key;
}

// Which members a keyframe gives, for the rule that every keyframe gives the same.
std::string members(const Keyframe& k) {
    std::string s;
    const auto add = [&s](bool has, const char* name) {
        if (has) s += (s.empty() ? "" : ", ") + std::string(name);
    };
    add(k.cameraPosition.has_value(), "camera");
    add(k.cameraUp.has_value(), "camera.up");
    add(k.lightPosition.has_value(), "light.position");
    add(k.lightDirection.has_value(), "light.direction");
    return s.empty() ? "nothing" : s;
}

}  // namespace

MotionPath parseKeyframes(const std::string& json, const std::string& source) {
    const std::string problem = jsonProblem(json, 8);
    if (!problem.empty()) throw InputError("keyframe file '" + source + "': " + problem);
    const nlohmann::json doc = nlohmann::json::parse(json);
    const std::string context = "keyframe file '" + source + "'";
    if (!doc.is_object()) throw InputError(context + " must hold an object with 'keyframes'");
    onlyKeys(doc, {"keyframes"}, context);
    if (!doc.contains("keyframes") || !doc.at("keyframes").is_array() || doc.at("keyframes").empty())
        throw InputError(context + " needs a non-empty array 'keyframes'");
    const nlohmann::json& keys = doc.at("keyframes");
    if (keys.size() > kMaxKeyframes)
        throw InputError(context + " has " + std::to_string(keys.size()) + " keyframes (at most " +
                         std::to_string(kMaxKeyframes) + ")");
    MotionPath path;
    path.text = source;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        Keyframe k = keyframe(keys[i], where(source, i));
        if (i > 0) {
            const Keyframe& previous = path.keyframes.back();
            if (!(k.time > previous.time))
                throw InputError(where(source, i) + ": 't' must be greater than the previous keyframe's");
            if (members(k) != members(previous))
                throw InputError(where(source, i) + " gives " + members(k) + " where keyframe " + std::to_string(i) +
                                 " gives " + members(previous) + " (every keyframe gives the same)");
        }
        path.keyframes.push_back(std::move(k));
    }
    if (members(path.keyframes.front()) == "nothing")
        throw InputError(context + ": the keyframes move nothing (give 'camera' or 'light')");
    return path;
}

MotionPath parseMotionPath(const std::string& text) {
    if (text.empty()) throw InputError("path is empty (known motions: " + std::string(kKnown) + ")");
    if (lower(text).ends_with(".json")) {
        std::error_code ec;
        const auto bytes = std::filesystem::file_size(text, ec);
        if (ec) throw InputError("keyframe file '" + text + "' cannot be read (" + ec.message() + ")");
        if (bytes > kMaxFileBytes) throw InputError("keyframe file '" + text + "' is larger than 64 MiB");
        std::ifstream in(text, std::ios::binary);
        std::stringstream content;
        content << in.rdbuf();
        if (!in) throw InputError("keyframe file '" + text + "' cannot be read");
        return parseKeyframes(content.str(), text);
    }
    MotionPath path;
    path.text = text;
    for (std::size_t start = 0;;) {
        const std::size_t comma = text.find(',', start);
        path.motions.push_back(motion(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start), text));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return path;
}

}  // namespace viz::scene
