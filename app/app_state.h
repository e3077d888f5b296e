// The window's state as one plain value: what the user chose (scene, technique, settings, stepping
// cursor, camera, exposure, the view grid with each view's display settings, the inspected pixel, the
// lights). The session file, a lesson's window state and the state part of the screenshot sidecar are
// each derived from it by one function here, so the three cannot disagree.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "debug/technique.h"
#include "lesson_player.h"
#include "pane_image.h"
#include "run_scheduler.h"
#include "scene/scene.h"
#include "session_state.h"

namespace airlight {

// What the user chose that the window keeps in this one value and nowhere else (GuiApp::mState): the
// scene source, the technique, the render size, its settings, the stepping cursor, the exposure, the
// picked light and the focused view.
struct HeldState {
    std::string scene;                 // built-in name, stiff/ID or a .gltf/.glb path
    std::string technique;
    glm::ivec2 size{320, 240};         // render size
    viz::Settings settings;            // complete, for `technique`; the sub-step parameters at their defaults
    StepCursor cursor;                 // stage -1: the complete frame
    float exposure = 0.0f;
    bool exposureSet = false;
    int selectedLight = 0;             // the light the panel and the gizmo edit
    int focusedView = 1;               // keys, the views list and exports act on it
};

// The held state with what its owners keep beside it, taken as one value when a session, a lesson state
// or a sidecar is written: the camera (the camera controller), the medium and lights (the scene the
// runs read), the view grid (the layout and its views), the inspected pixel (the ray inspector).
struct AppState : HeldState {
    viz::Settings defaults;            // the technique's defaults (the session keeps only what differs)
    int stageShown = 0;                // the stage index the cursor resolves to
    viz::Settings steppedSettings;     // `settings` with the cursor's sub-step written as its stage's parameter
                                       // (how the command line and lessons say where a run stops)
    viz::scene::Camera camera;
    glm::dvec3 orbitTarget{0.0};
    bool flyCamera = false;
    viz::scene::Medium medium;
    std::vector<viz::scene::Light> lights;
    struct View {
        int id = 0;
        std::string content = "airlight";
        int layer = 0;
        double zoom = 1.0;
        glm::dvec2 center{0.5};
        DisplaySettings display;
    };
    std::string layout;                // ViewLayout::toText()
    int maximisedView = -1;
    std::vector<View> views;           // in the layout's reading order
    std::optional<glm::ivec2> inspected;  // the ray inspector's pixel (or a lesson step's, pending)
};

// The session file's contents. `base` carries what the app state does not hold: the other techniques'
// saved settings and the lesson's position (written by the lesson player).
SessionState sessionOf(const AppState& state, SessionState base);
// What a lesson step compares with and applies: the settings speak for the cursor (its sub-step is the
// stage's parameter there), the view is the focused one.
LessonWindowState lessonStateOf(const AppState& state);
// The state part of the screenshot sidecar (settings by name, camera, exposure, cursor, selection).
nlohmann::json sidecarStateOf(const AppState& state);

}  // namespace airlight
