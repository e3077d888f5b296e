// The window's session: what the user set up, saved to a small JSON file (F5, and on exit) and loaded
// back (F9, --state FILE, and at start). F9 never fails hard: a missing, truncated or corrupted file loads
// nothing, the window keeps its session, and a one-line reason names the file. A file named with --state that exists and is not a
// session stops the window before it opens, the file untouched.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "debug/technique.h"
#include "scene/scene.h"

namespace airlight {

struct SessionState {
    static constexpr int kVersion = 1;
    std::string scene;                       // built-in name, stiff/ID or glTF path; empty = default
    std::string technique;                   // empty = default
    int width = 320, height = 240;           // render size
    std::optional<viz::scene::Camera> camera;  // empty = the scene's own
    glm::dvec3 orbitTarget{0.0};
    std::optional<viz::scene::Medium> medium;  // empty = the scene's own
    // Where the user put the scene's lights and how bright (panel or gizmo), in the scene's order; empty =
    // the scene's own. Applied only to the same scene with as many lights.
    struct LightPlacement {
        glm::dvec3 position{0.0};
        glm::dvec3 direction{0.0, 0.0, -1.0};  // unit
        double intensity = 1.0;
    };
    std::vector<LightPlacement> lights;
    std::map<std::string, viz::Settings> settings;  // per technique id, only values the user set
    std::string view = "airlight";          // the intermediate shown beside the final frame
    double viewZoom = 1.0;                   // its pan and zoom (ui/image_view.h)
    glm::dvec2 viewCenter{0.5};
    float exposure = 0.0f;                   // EV
    bool exposureSet = false;
    // The lesson player's position (empty lesson: no lesson open). With tryIt the fields above hold what
    // the student changed from the step; without it the step's own state is shown.
    std::string lesson;                      // path of the lesson's .md file
    int lessonStep = 0;                      // 0-based
    bool lessonTryIt = false;

    // ---- the view grid (app/view_layout.h); empty layout = the default, the final frame beside `view` ----
    struct GridView {
        int id = 0;                          // the layout's view number
        std::string content = "airlight";    // "final", "airlight" or an intermediate id
        int layer = 0;
        double zoom = 1.0;
        glm::dvec2 center{0.5};
        // Display settings (app/pane_image.h DisplaySettings), as their enum values.
        int channel = 0, range = 0, colourMap = 0, difference = 0;
        float manualMin = 0.0f, manualMax = 1.0f;
        int markNegative = -1;  // -1 auto, 0 off, 1 on
        bool logScale = false, stripOpen = false;
        std::string against = "reference";
    };
    std::string layout;            // ViewLayout::toText()
    int focusedView = -1, maximisedView = -1;
    std::vector<GridView> gridViews;
};

std::string sessionToJson(const SessionState& state);
// The lights' placements of `scene`, and applying saved ones to it (false, scene unchanged, when the
// number of lights differs).
std::vector<SessionState::LightPlacement> lightPlacements(const viz::scene::Scene& scene);
bool applyLightPlacements(const std::vector<SessionState::LightPlacement>& placements, viz::scene::Scene& scene);
// Parses `text`; on any problem returns the defaults and sets `problem` to a one-line reason.
SessionState sessionFromJson(const std::string& text, std::string& problem);

// The default location: $XDG_STATE_HOME/airlight/session.json, else ~/.local/state/airlight/session.json.
std::string defaultSessionPath();

// Reads `path`, never touching the file: `state` holds the defaults unless `file` is Loaded, and `problem`
// a one-line reason naming the file ("state file 'P': ...") unless it is.
struct SessionRead {
    enum class File { Loaded, Missing, Broken };  // Broken: unreadable, not a regular file, or bad contents
    File file = File::Missing;
    SessionState state;
    std::string problem;
};
SessionRead readSession(const std::string& path);
// As readSession, for F9: a missing or unreadable file, or bad contents, give the defaults and a reason
// saying "nothing loaded" (the window keeps its current session). A regular file with bad contents is moved aside first, to the first free
// name of P.broken, P.broken.2, ... (the window saves over P later, and a hand edit must survive). An
// empty reason means the state was loaded.
SessionState loadSession(const std::string& path, std::string& problem);
// For `gui --state P` at start: the file the user named must be a session or not exist yet (the window
// then starts one there). Anything else is an InputError and the file is left exactly as it is: a
// mistyped path (`--state scene.gltf`) must never be renamed or saved over.
SessionRead loadNamedSession(const std::string& path);
// Writes atomically (creating the folder); throws InputError naming the path on failure.
void saveSession(const std::string& path, const SessionState& state);

}  // namespace airlight
