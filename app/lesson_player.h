// The lesson player: a side panel in the window with a lesson's text (our minimal Markdown, word-wrapped
// and scrollable), a step counter, Previous / Next, a "Try it" mode and the step's animation. It owns the
// lesson position and the try-it bookkeeping; the window applies a step through its own state changes
// (LessonHost, implemented by the window), so a step shows exactly what the same clicks would show.
//
// Keys (while a lesson is open): PageUp / PageDown previous / next step, T try it on/off, B back to the
// step, Space play/pause the step's animation (only when the step has one; otherwise Space stays with
// the widgets).
//
// Try it: outside try-it mode any change the student makes (a parameter, the camera, the technique, the
// inspected pixel, the view) switches try-it on; the panel then says "changed from the step", and
// "Back to the step" (or leaving try-it mode) applies the step's state again exactly.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "debug/technique.h"
#include "lesson.h"
#include "scene/light_orbit.h"
#include "scene/scene.h"
#include "session_state.h"
#include "ui/immediate.h"
#include "ui/text_renderer.h"

namespace airlight {

// What a step sets in the window, and what the window reports back to compare with it.
struct LessonWindowState {
    std::string scene;       // as named in the lesson (built-in, stiff/ID or glTF path)
    std::string technique;
    glm::ivec2 size{0};      // render size
    viz::Settings settings;  // complete: every parameter of the technique
    int stage = -1;          // index of the last stage run (the last index: everything runs)
    std::string view;        // the right-hand view: "airlight" or an intermediate id
    // Every right-hand view of the step, `view` first (the player fills it; the window lays out up to
    // three of them beside the final frame). Empty in a state read back from the window.
    std::vector<std::string> views;
    std::optional<glm::ivec2> inspect;  // the ray inspector's pixel (image convention, row 0 at the top)
    viz::scene::Camera camera;
    glm::dvec3 orbitTarget{0.0};
    viz::scene::Medium medium;
    std::vector<viz::scene::Light> lights;
};

// The window's side of the player.
class LessonHost {
public:
    virtual ~LessonHost() = default;
    // Loads a scene; its camera, medium and lights become the window's. Throws InputError when the scene
    // cannot be loaded (the window keeps the scene it had).
    virtual void loadLessonScene(const std::string& name) = 0;
    virtual LessonWindowState lessonWindowState() const = 0;
    // Technique, size, settings, stage, right-hand view, inspected pixel, camera, medium and lights
    // (the scene is the one loaded last).
    virtual void applyLessonWindowState(const LessonWindowState& state) = 0;
    // The right-hand pane shows another of the step's views.
    virtual void showLessonView(const std::string& id) = 0;
    // One frame of an animation: a setting (the sub-step parameter) or the first light.
    virtual void setLessonSetting(const std::string& name, double value) = 0;
    virtual void setLessonLight(const viz::scene::Light& light) = 0;
    // A session restored in try-it mode: its technique, settings, medium, camera and view over the step.
    virtual void restoreSessionOverStep() = 0;
    // The step's live comparison (`compare:`): the comparison grid with the reference and these
    // techniques, timed on this machine; empty: no grid.
    virtual void showLessonComparison(const std::vector<std::string>& techniques) = 0;
    // The caption the window's view title gives a view id ("final", "airlight" or an intermediate of the
    // last run); the id itself when the last run did not publish it.
    virtual std::string lessonViewCaption(const std::string& id) const = 0;
    // The sub-steps of stage `stage` as the last run counted them, where a run knows fewer than the
    // settings list (minmax's walk: the picked ray's nodes); a `substeps` animation ends there.
    virtual int lessonSubstepCount(int stage) const {
        (void)stage;
        return std::numeric_limits<int>::max();
    }
};

// The first light of a step's `animate: light orbit` at `turn` (0..1, one full turn): scene/light_orbit.h.
using viz::scene::kOrbitTilt;
using viz::scene::orbitLight;

class LessonPlayer {
public:
    // `path`: the lesson's .md file. A malformed lesson does not throw: the panel shows the error
    // (FILE:LINE: reason) and a Reload button. sizeOverride (non-zero): every step renders at that size
    // (its inspected pixel scaled along).
    LessonPlayer(std::string path, glm::ivec2 sizeOverride);

    // Once per frame, before the window renders: runs what the buttons and keys asked for, applies the
    // step when it is due, advances the animation by dt seconds and compares the window with the step.
    void update(LessonHost& host, double dt);
    // Keys (GLFW codes); true when the player used the key. Auto-repeat steps on, but toggles nothing.
    bool onKey(int key, bool repeat);
    // The wheel over the panel scrolls its text (lines, + = towards the top).
    void scroll(float lines);

    // Layout: the panel's width for a window `windowWidth` pixels wide, and where it goes this frame.
    static float panelWidth(float windowWidth, float scale);
    void place(const viz::ui::Rect& area) { mArea = area; }
    const viz::ui::Rect& area() const { return mArea; }
    // Draws the panel: backgrounds into `background`, text into `text`, buttons with `ui` (inside its
    // frame). Clicks are queued and run at the next update(). `host` names the step's views as the
    // window does.
    void draw(const LessonHost& host, viz::ui::Context& ui, viz::ui::DrawList& text, viz::ui::DrawList& background,
              float scale);

    bool animating() const { return mPlaying; }
    // Position in the session file, and back.
    void saveTo(SessionState& session) const;
    void restore(int step, bool tryIt);
    // The "lesson" object of the screenshot sidecar.
    nlohmann::json sidecar(const LessonHost& host) const;

private:
    enum class Action { Previous, Next, Back, ToggleTryIt, PlayPause, Reload, ShowView };
    void open();
    void applyStep(LessonHost& host);
    void animate(LessonHost& host);
    bool matches(const LessonWindowState& now) const;
    std::vector<std::string> rightViews() const;  // the step's views the right-hand pane may show
    const LessonStep* step() const { return mLesson && mStep < int(mLesson->steps.size()) ? &mLesson->steps[std::size_t(mStep)] : nullptr; }

    std::string mPath;
    glm::ivec2 mSizeOverride{0};
    std::optional<Lesson> mLesson;
    std::string mStepParamsFor;              // the technique whose parameters mStepParams holds
    std::vector<viz::ParamInfo> mStepParams;  // to show a step's settings by name (integrand=svd)
    std::string mLoadError;  // the lesson file's problem (FILE:LINE: reason)
    std::string mStepError;  // the current step's problem when applying it
    int mStep = 0;
    bool mTryIt = false;
    bool mDue = true;          // apply the step at the next update
    bool mRestoreTryIt = false;  // after that, put the session's try-it state back on top
    std::vector<std::pair<Action, std::string>> mActions;

    // The step as applied, and whether the window still shows it (checked every update).
    std::optional<LessonWindowState> mWanted;
    bool mMatches = false;
    std::string mShownView;  // the window's right-hand view at the last update
    // The scene's own camera, medium and lights, captured when the player loaded it.
    std::optional<LessonWindowState> mBase;
    std::string mSubstepParam;          // a substeps animation: the parameter and its value per sub-step
    std::vector<double> mSubstepValues;  // (Technique::substepValues; the last one runs the stage whole)
    int mSubstepStage = -1;              // the stage they step
    int mSubstepShown = 0;               // how many the animation goes through (LessonHost::lessonSubstepCount)
    glm::dvec3 mOrbitCentre{0.0};

    bool mPlaying = false;
    double mTime = 0.0;  // seconds into the animation

    viz::ui::Rect mArea;
    float mScroll = 0.0f, mContentHeight = 0.0f;
    float mLine = 18.0f;  // the font's line height (scrolling by lines)
};

}  // namespace airlight
