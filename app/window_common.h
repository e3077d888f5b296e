// The window's shared vocabulary: its palette and sizes, and the small helpers its parts share (settings
// completed with defaults, a message's first line, the orbit distance of a scene, GLFW keys the widgets take).
#pragma once

#include <chrono>
#include <exception>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/error.h"
#include "core/text.h"
#include "debug/technique.h"
#include "run_scheduler.h"
#include "scene/orbit_target.h"
#include "scene/scene.h"
#include "ui/font.h"
#include "ui/immediate.h"
#include "ui/theme.h"
#include "text_fit.h"

namespace airlight {


using viz::ui::DrawList;
using viz::ui::Rect;
using Clock = std::chrono::steady_clock;

// ---- colours (display values) and sizes (logical pixels, times the content scale) ----
// The palette and the base sizes are the one theme's (viz/ui/theme.h); the window's own sizes follow.
using viz::ui::theme::kAccent;
using viz::ui::theme::kBackground;
using viz::ui::theme::kDim;
using viz::ui::theme::kError;
using viz::ui::theme::kFontSize;
using viz::ui::theme::kHighlight;
using viz::ui::theme::kHover;
using viz::ui::theme::kPad;
using viz::ui::theme::kPanel;
using viz::ui::theme::kText;
constexpr double kGizmoArm = 0.25;  // the light gizmo's direction arm, in orbit distances of the scene camera
constexpr float kSidebarMin = 170.0f;
constexpr float kExposureStep = 0.5f;  // stops per +/- key press
constexpr double kOrbitRadiansPerPixel = 0.008;
constexpr double kLookRadiansPerPixel = 0.004;
constexpr double kFlySpeed = 0.6;  // target distances per second

// ---- settings ----

// The given settings that this technique has a parameter for, completed with its defaults. A value
// the technique rejects is reported in `error` and the defaults are used instead.
inline viz::Settings settingsFor(const viz::Technique& technique, const viz::Settings& given, std::string& error) {
    viz::Settings mine;
    for (const auto& [name, value] : given) {
        for (const viz::ParamInfo& p : technique.params())
            if (p.name == name) mine[name] = value;
    }
    try {
        return viz::completeSettings(technique, mine);
    } catch (const viz::InputError& e) {
        error = e.what();
        return viz::completeSettings(technique, {});
    }
}

// The stage whose sub-step parameter `name` is (StageInfo::substepParam), or -1.
inline int substepStageOf(const viz::Technique& technique, const std::string& name) {
    const auto& stages = technique.stages();
    for (int k = 0; k < int(stages.size()); ++k)
        if (stages[std::size_t(k)].substepParam == name) return k;
    return -1;
}

// The window steps with its cursor, never with settings: takes the sub-step parameters out of `settings`
// (back to their defaults) and returns the cursor that the first one set away from its default stands
// for (the command line's `gui --set planes_drawn=7`, a session file), if any. `onlyStage` >= 0: only
// that stage's parameter (a lesson step stopping there); the others stay as the lesson set them.
inline std::optional<StepCursor> takeSubsteps(const viz::Technique& technique, viz::Settings& settings, int onlyStage = -1) {
    std::optional<StepCursor> cursor;
    const viz::Settings defaults = viz::completeSettings(technique, {});
    const auto& stages = technique.stages();
    for (int k = 0; k < int(stages.size()); ++k) {
        const std::string& name = stages[std::size_t(k)].substepParam;
        if (name.empty() || !settings.count(name) || (onlyStage >= 0 && k != onlyStage)) continue;
        const viz::SubstepPosition pos = viz::substepPosition(technique, k, settings);
        settings[name] = defaults.at(name);
        if (!cursor && pos.at < pos.count) cursor = StepCursor{k, pos.at};
    }
    return cursor;
}

// ---- formatting ----

// Error messages (shader logs) can span lines; the status line shows the first, marked when there is more.
inline std::string firstLine(const std::string& text) { return viz::firstLine(text, "  (...)"); }

using viz::format;


// A light's kind as the panel names it.
inline const char* lightTypeName(viz::scene::LightType type) {
    switch (type) {
        case viz::scene::LightType::Point: return "point";
        case viz::scene::LightType::Spot: return "spot";
        case viz::scene::LightType::Directional: return "directional";
        case viz::scene::LightType::Area: return "area";
    }
    return "light";
}

// The orbit target's distance from the scene camera (scene/orbit_target.h).
using viz::scene::orbitDistance;

// ---- the app ----

// The keys the widgets use, from GLFW's; others stay with the window's own shortcuts.
inline std::optional<viz::ui::Key> uiKey(int key) {
    switch (key) {
        case GLFW_KEY_ENTER: case GLFW_KEY_KP_ENTER: return viz::ui::Key::Enter;
        case GLFW_KEY_SPACE: return viz::ui::Key::Space;
        case GLFW_KEY_LEFT: return viz::ui::Key::Left;
        case GLFW_KEY_RIGHT: return viz::ui::Key::Right;
        case GLFW_KEY_UP: return viz::ui::Key::Up;
        case GLFW_KEY_DOWN: return viz::ui::Key::Down;
        case GLFW_KEY_BACKSPACE: return viz::ui::Key::Backspace;
        case GLFW_KEY_DELETE: return viz::ui::Key::Delete;
        case GLFW_KEY_HOME: return viz::ui::Key::Home;
        case GLFW_KEY_END: return viz::ui::Key::End;
        case GLFW_KEY_ESCAPE: return viz::ui::Key::Escape;
        default: return std::nullopt;
    }
}

// A light gizmo handle being dragged (GuiApp::mGizmoDrag).
struct GizmoDrag {
    int view = -1;
    bool direction = false;  // the direction handle (else the position handle)
    glm::dvec2 offset{0.0};  // from the cursor to the handle at the press, in frame uv (drags render at
                             // half size): the handle keeps it
};

// What the loader decided on its own about a scene (a default light, a medium typo, repaired normals),
// for the status line: "scene notes: A; B".
inline std::string sceneNotesLine(const viz::scene::Scene& scene) {
    std::string line;
    for (const std::string& n : scene.notes) line += (line.empty() ? "scene notes: " : "; ") + n;
    return line;
}

}  // namespace airlight
