// The window's application object: one GLFW window, its state and its parts. The class is declared here
// and defined by concept across app/window_*.cpp (automation, session and lesson host, input, panes, view
// drawing, gizmo, inspector, tools, frame, parameters, animation); gui.cpp holds the frame loop and the runs.
#pragma once

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <initializer_list>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "camera_controller.h"
#include "comparison_grid.h"
#include "comparison_panel.h"
#include "cpu_worker.h"
#include "difference_runs.h"
#include "display_strip.h"
#include "lesson_player.h"
#include "parameter_panel.h"
#include "pane_image.h"
#include "process_stats.h"
#include "ray_inspection.h"
#include "ray_inspector.h"
#include "reload_merge.h"
#include "frame_canvas.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_io.h"
#include "gl/debug_output.h"
#include "gl/program.h"
#include "gl/readback.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "platform/window_glfw.h"
#include "render_job.h"
#include "run_pool.h"
#include "run_scheduler.h"
#include "screen_map.h"
#include "sidebar.h"
#include "status_bar.h"
#include "step_timeline.h"
#include "window_animation.h"
#include "scene/scene_source.h"
#include "scene/stiff_scenes.h"
#include "scene/builtin_scenes.h"
#include "session_state.h"
#include "sidecar_json.h"
#include "image_fit.h"
#include "light_gizmo.h"
#include "view_grid.h"
#include "view_layout.h"
#include "view_state.h"
#include "view_title.h"
#include "view_cell.h"
#include "view_stats.h"
#include "techniques/registry.h"
#include "plot/plot.h"
#include "report/error_metrics.h"
#include "techniques/reference/ray_probe.h"
#include "ui/font.h"
#include "ui/immediate.h"
#include "ui/text_renderer.h"

#include "gui.h"
#include "app_state.h"
#include "input_table.h"
#include "scene_file.h"
#include "script_player.h"
#include "window_common.h"

namespace airlight {

class GuiApp : public LessonHost, private ScriptHost {
public:
    // fileLighting: the scene's medium and lights as its file gave them, before a session's edits.
    GuiApp(const GuiOptions& options, viz::scene::Scene scene, SceneLighting fileLighting, viz::Window& window,
           SessionState session, std::string notice);
    ~GuiApp();
    int run();

    // The back buffer as drawn (before the swap) to the PNG, and the views' rectangles beside it.
    // The window as PNG (when `image`) and its sidecar JSON (the same path, .json).
    void writeScreenshot(const std::string& path, bool image = true);
    void writeWindowImage(const std::string& path);
    void writeSidecar(const std::string& path);

private:
    // ---- ScriptHost: the script player's actions on the window (script_player.h) ----

    std::optional<Rect> scriptRect(const std::string& name) const override;
    std::string knownNames() const override;
    bool isWidget(const std::string& name) const override;
    void revealWidget(const std::string& name) override;
    void pressKey(int key, int modifiers) override;
    void typeText(const std::string& text) override;
    void dropFile(const std::string& path) override;
    void hoverAt(glm::vec2 p) override;
    void dragTo(glm::vec2 p) override;
    void leftButton(bool press, glm::vec2 p) override;
    void wheel(float notches) override;
    void screenshot(const std::string& path, bool image) override;
    bool appendStats(const std::string& path) override;

    // ---- the session file ----

    // The window's state as one value (app_state.h); the session, the lesson state and the sidecar's
    // state part are derived from it.
    AppState appState() const;
    SessionState currentSession() const;
    void saveSessionNow();
    void loadSessionNow();

    // The session's medium, technique (with its settings), camera, view and exposure over the scene.
    void restoreSessionOverStep() override;
    void showLessonComparison(const std::vector<std::string>& techniques) override;
    std::string lessonViewCaption(const std::string& id) const override;
    // Opens the comparison grid on the current view for these techniques (an error goes to the status).
    void openComparison(const std::vector<std::string>& ids);

    // ---- the lesson player's hooks (lesson_player.h): the window's own state changes ----

    void loadLessonScene(const std::string& name) override;
    LessonWindowState lessonWindowState() const override;
    void applyLessonWindowState(const LessonWindowState& s) override;
    void showLessonView(const std::string& id) override;

    // A lesson's view goes to the focused view of the grid (the right-hand one by default).
    void showInFocusedView(const std::string& id);
    void setLessonSetting(const std::string& name, double value) override;
    int lessonSubstepCount(int stage) const override;

    // ---- animation (P): the first light circles its aim point (or --path's motion plays), a `time`
    // parameter (slices' noise) follows the clock. GPU techniques run every frame while it plays; the
    // reference keeps the light where it is. A pause keeps the state; playing again continues from there.
    static constexpr double kLightTurnSeconds = 8.0;
    void togglePlaying();
    // Runs a technique for the comparison grid with the window's settings for it.
    ComparisonGrid::RunTechnique comparisonRunner();
    void advanceAnimation(double dt);
    void startPathLoop();           // --path: frame 0 is the camera and lights as they are now
    void playPathFrame(int frame);  // --path: frame `frame` of the loop, from where it started
    // --path: the reference's L_air on the frame shown, for the main views' temporal view or the
    // comparison grid's tiles (at its size and camera); null until known.
    std::shared_ptr<const viz::Image> pathReferenceFrame(bool forGrid = false);
    void setLessonLight(const viz::scene::Light& light) override;

    // Camera, view and exposure of the session (the scene, medium and technique are applied before).
    void applySessionView();

    // ---- comparison grid ----

    // G: the comparison grid (comparison_grid.h) for the current view; G again closes it.
    void toggleComparison();

    // The grid's techniques with the window's instances and settings (this thread holds the GL context).
    void runComparisonTechniques();

    // ---- export ----

    // Files go to --export-dir (default airlight-exports/ in the working folder), named after the scene,
    // technique and view, so that successive exports of different views do not overwrite each other.
    // DIR/scene-technique-WHAT, numbered (-2, -3, ...) past the names whose files exist; InputError when
    // kMaxExportsOfOneName are taken.
    static constexpr int kMaxExportsOfOneName = 9999;
    std::string exportStem(const std::string& what, std::initializer_list<const char*> extensions);

    // E: the intermediate view as EXR (its float values) and PNG (as shown: exposure or range mapping).
    void exportView();
    // The focused view as its export shows it: linear values and the exposure scale a PNG applies (false
    // when it holds no image).
    bool focusedViewImage(viz::Image& image, float& exposure);
    // E while playing starts or stops recording the focused view; stopping writes the GIF.
    void toggleRecording();
    void stopRecording();

    // F12: the whole window as PNG (with its sidecar JSON of view rectangles).
    void exportWindow();

    // ---- stepping ----

    // The stage the cursor stands in (the last one for the complete frame).
    int stageShown() const;

    // The cursor's sub-step position: {at, count} (1-based; {count, count} when the stage runs whole,
    // {0, 0} for a stage without sub-steps).
    std::pair<int, int> substepState() const;
    // What the status lines say (status_bar.h), with the shown timing's clock named.
    StatusFacts statusFacts(const viz::Timing& timing) const;

    // Whether the frame is the complete algorithm: the last stage, whole, and no sub-step parameter a
    // lesson (or --set) left cutting an earlier stage short.
    std::string stoppedEarly() const;
    void moveCursor(StepCursor c);

    // S / Shift+S: the next / previous stage, wrapping (the last stage is the complete frame). A stage
    // with sub-steps is entered at its first.
    void stepStage(int delta);

    // D / Shift+D: one sub-step more / fewer inside the current stage; Home / End: the first / last.
    void stepSubstep(int delta);
    void setSubstepAt(int k);

    // The timeline under the views: a click or a drag puts the cursor there (step_timeline.h).
    void drawStepTimeline();

    // ---- ray inspector ----

    // The exact ground truth along the ray of the final image's pixel under the cursor, beside the current
    // technique's value for that pixel. The cursor elsewhere clears it.
    void inspectPixelUnderCursor();
    void inspectPixel(int x, int y);
    // The technique's readings at the inspected pixel when the run shown is the inspected technique's
    // (null otherwise): read back once per run and pixel.
    const PixelInspection* inspectedReadings();

    // ---- techniques and rendering ----

    // The main views' instance of the current technique (its own: no other consumer runs it).
    viz::Technique& technique() { return mRuns.runner(Consumer::Views, mState.technique).technique(); }
    const viz::Technique& technique() const { return mRuns.at(Consumer::Views, mState.technique).technique(); }
    // mState.technique's place in mIds (the technique list, N and Shift+N).
    int currentIndex() const;

    void selectTechnique(int index);
    void render();
    void acceptCpuResult(CpuResult result);

    // ---- the view grid: what each view shows ----

    // Contents in the views list: the final frame, L_air, then every intermediate of the run.
    int contentCount() const;
    // What the grid's views show (content ids), for the run's on-demand views.
    std::vector<std::string> shownContents() const;
    std::string contentId(int index) const;
    std::string contentLabel(int index) const;
    // The content index (0 final, 1 L_air, 2 + i intermediate i) of the first content with this id in the
    // last run; -1 when it has none.
    int contentIndexOf(const std::string& id) const;
    ViewState& focusedView();
    void clearPanes();

    // The default grid: the final frame on the left, `content` on the right (focused).
    void resetLayout(const std::string& content);
    // A lesson step's views: the final frame and up to three of the step's right-hand views fill the
    // grid (one view: the grid keeps its layout and the focused view shows it).
    void layOutLessonViews(const std::vector<std::string>& views);

    // The session's grid, or the default one around its `view`.
    void applySessionGrid();

    // A view with one texel per frame pixel, so cursors link across such views (an orbit view is
    // frame-sized but seen from elsewhere).
    bool isScreenSpace(const ViewState& v) const;

    // Builds the view's pane from the last run (and its difference image in difference mode).
    void buildPane(ViewState& v);

    // Difference mode: this technique's image against the same image of `against` (same scene, camera,
    // size; that technique's own settings), as a heat map (or blue-white-red when signed), with the
    // report's error figures in the title.
    void makeDifference(ViewState& v, const std::string& content);

    // The other side of difference views (difference_runs.h): `id`'s images for the current scene,
    // camera and size, null while they are computed or during an interaction. The current technique is
    // its own last output.
    const DifferenceRuns::Run* otherRun(const std::string& id);
    // The window's request for `id` now (its settings completed by its technique where it can be made).
    DifferenceRequest differenceRequest(const std::string& id);

    // The settings `id` runs with (in the main views when it is picked, on the other side of a difference
    // view or in the comparison grid): the session's for it, then the command line's on top (a parameter
    // the user changes in the panel leaves the command line's); completed: over its technique's defaults
    // (throws for an id that makes no technique).
    viz::Settings givenSettings(const std::string& id) const;
    viz::Settings completedOtherSettings(const std::string& id);

    // The GPU runs queued by otherRun (this blocks the thread; the frame before said "computing it..."),
    // and the worker's finished pass: each refreshes the views that compare against its technique.
    void runDueGpuOthers();
    void pollOtherWorker();
    void refreshDifferenceViews(const std::string& against);
    void refreshView(ViewState& v);

    void refreshPanes();

    // [ ] and the views list: what the focused view shows.
    void stepView(int delta);
    void selectView(int index);
    void stepLayer(int delta);

    // H / J: a new view beside / below the focused one, showing the content after the focused one's.
    void splitFocused(SplitAxis axis);

    // K: closes the focused view (not the last one).
    void closeFocused();

    // O / Shift+O: the focused view trades places with the next / previous one (it keeps the focus).
    void swapFocused(int step);

    // F: the focused view's difference to the reference on or off (final frame and L_air views).
    void toggleDifference();

    // ---- input ----

    glm::vec2 cursorPixels(double x, double y) const;

    // Keys are dispatched from one table (input_table.h), which also writes the help lines and README.
    void onKey(int key, int action, int mods);
    void perform(Command command, int offset);
    void onChar(unsigned codepoint);
    void onDrop(const std::vector<std::string>& paths);
    void onMouseButton(int button, int action);
    void onMouseButtonAt(int button, int action, glm::vec2 p);
    void onCursor(double x, double y);

    // Orbit views (render::MeshView: polyvol's light volume, slices' planes) turn with a left drag:
    // their mesh_yaw / mesh_pitch parameters, 0.4 degrees per pixel.
    bool isOrbitView(const ViewState& v) const;
    void turnOrbitView(glm::vec2 d);
    void onCursorPixels(glm::vec2 p);
    void onScroll(double dy);

    // A key held down, by the user or by a script's `hold`.
    bool keyDown(int key) const;
    bool anyFlyKeyDown() const;
    void fly(double dt);

    // ---- drawing ----

    // ---- the light gizmo (light_gizmo.h): the first light's handles over the frame views ----

    std::optional<LightGizmo> gizmoFor(const ViewState& v) const;

    // Frame pixels (continuous, y down) <-> window pixels, through the view's pan and zoom.
    static glm::vec2 frameToWindow(const ViewState& v, glm::dvec2 px);
    static glm::dvec2 windowToFrame(const ViewState& v, glm::vec2 p);

    // Where a handle is drawn and grabbed: its window point, or (off the view) the nearest point just
    // inside the image's edge; `inside` says which.
    glm::vec2 handlePoint(const ViewState& v, glm::dvec2 px, bool& inside) const;

    // The handle under `p` (the direction handle first: it is the smaller target), within 8 pixels.
    // Drags are relative: a handle off the view is grabbed at the view's edge and follows the cursor.
    std::optional<GizmoDrag> gizmoHandleAt(glm::vec2 p) const;
    void dragGizmo(glm::vec2 p);

    // The first light's handles: a square at its position (point, spot), a diamond at the end of its
    // direction arm (spot: where the light goes; directional: where it comes from, the arm ending at
    // the orbit target). Scripts name them "gizmo:position" and "gizmo:direction" (in the first view
    // that shows them).
    void drawGizmo(DrawList& dl, int id, const ViewState& v);

    // The scene's medium or lights changed (panel, gizmo): the CPU worker keeps its own copy of the
    // scene, and the plan may change.
    void sceneEdited();

    // The gaps between views: each is the toolkit's splitter over its split (scripts name them
    // "divider:root", "divider:1", ... by the split's path).
    void drawDividers(const Rect& area);

    // The window's cursor shows a divider can be dragged.
    void setResizeCursor(std::optional<SplitAxis> axis);
    void drawViewGrid(const Rect& area);

    // What every view cell (view_cell.h) needs from the window this frame: the canvas, the mouse, the
    // focus, where the run stopped, the titles' facts, the progress bands.
    ViewCellFrame cellFrame();
    // One cell (view_cell.h) with the window's parts: the linked pixel's marks, the ray inspector's mark,
    // the light gizmo, the display strip's toggle, and the strip's widgets after it.
    void drawView(const ViewCellFrame& frame, int id, ViewState& v);

    // The technique's marks for the linked pixel, asked once per pixel and run (a GPU technique may
    // read a texel back for them).
    std::vector<viz::ViewMarker> markersFor(const ViewState& v);

    // The view's display strip (display_strip.h) in its rectangle; re-does what its widgets changed.
    void drawStrip(int id, ViewState& v);

    // What the sidecar says of a view (tests assert on it).
    ViewSidecarFacts viewSidecarFacts(int id);
    void draw();

    // ---- scene and technique controls (immediate-mode widgets) ----

    // Medium and light sliders and the technique's parameters, generated from its declarations.
    // The widgets' frame starts before the view grid (its display strips) and ends after this panel.
    void beginWidgets(glm::ivec2 fb);
    void drawParameters(glm::ivec2 fb);

    // A scene picked in the panel, loaded before the next frame is laid out (a scene that fails to load
    // leaves the current one and shows the error).
    void loadPendingScene();
    void setUiScale(float scale);
    void toggleFullscreen();
    // File > Open, a drop, a script's `drop`: a scene file to load before the next frame (errors in the
    // status line; the window keeps its scene).
    void openSceneFile(const std::string& path);
    // The scene file changed on disk: loaded again keeping the camera, the view grid and the settings.
    void reloadScene();
    // The scene as the window names it: a file's name (and its glTF scene's, when that differs).
    std::string sceneTitle() const;
    // The light the panel and the gizmo edit (the scene's first unless another is picked in the panel).
    int selectedLightIndex() const { return std::clamp(mState.selectedLight, 0, std::max(0, int(mScene.lights.size()) - 1)); }
    viz::scene::Light& selectedLight() { return mScene.lights[std::size_t(selectedLightIndex())]; }
    const viz::scene::Light& selectedLight() const { return mScene.lights[std::size_t(selectedLightIndex())]; }

    void replan();

    GuiOptions mOptions;
    long mGlErrors = 0;  // GL errors seen by the script's stats actions
    ScriptPlayer mScript;  // gui --script
    WindowAnimation mAnimation;  // P
    SessionState mSession;  // as loaded (or defaults); settings of techniques not yet visited come from it
    std::string mNotice;    // last session message, shown in the status line
    viz::scene::Scene mScene;  // the camera follows the controller; stamped on every load (geometryKey)
    viz::Window& mWindow;
    SceneLighting mFileLighting;  // the medium and lights as the scene file gave them (reload_merge.h)
    CameraController mController;
    double mGizmoArm = 1.0;  // scene units (kGizmoArm of the scene camera's orbit distance)
    std::vector<std::string> mIds;
    // Every technique instance, by consumer: the main views' (their panes borrow its textures) and the
    // others' (difference views, the comparison grid: both copy their images out).
    RunPool mRuns;
    // What the user chose, held here only (app_state.h): scene source, technique, size, settings, stepping
    // cursor (not a setting), exposure, picked light, focused view. appState() adds what the camera
    // controller, the scene, the grid and the inspector keep.
    HeldState mState;
    viz::Plan mPlan;
    const viz::Plan& shownPlan() const { return mHaveOutput ? mOutput.plan : mPlan; }  // last run's, else mPlan
    std::string mSettingsError, mError, mClockName;
    std::unique_ptr<viz::StageTimer> mGpuTimer;  // main views' GPU runs where timer queries count (gl/gpu_timer.h)

    std::unique_ptr<viz::ui::FontAtlas> mFont;
    std::unique_ptr<viz::ui::TextRenderer> mTextRenderer;
    std::unique_ptr<DrawList> mDrawList;    // text and overlays, drawn last in one call
    std::unique_ptr<DrawList> mBackground;  // panels behind the images
    std::unique_ptr<ImageDisplay> mImageDisplay;
    // The main views' CPU worker (the pool's Worker::Views, made with the window).
    CpuWorker& cpuWorker() { return mRuns.worker(Worker::Views, mScene); }
    std::uint64_t mCpuShownTicket = 0;  // the request of the worker's pass the main views show (none older after it)
    float mScale = 1.0f;           // sizes' factor: the display's content scale times the UI scale
    float mContentScale = 1.0f;    // from GLFW (HiDPI)
    float mUiScale = 1.0f;         // --ui-scale, Ctrl+= / Ctrl+-
    static constexpr float kMinUiScale = 0.5f, kMaxUiScale = 4.0f;
    glm::ivec4 mWindowedRect{0, 0, 1280, 720};  // position and size before full screen (F11)
    int mElidedTitles = 0;         // view titles shortened to fit in the last frame (sidecar)

    viz::FrameOutput mOutput;
    bool mHaveOutput = false;
    glm::ivec2 mOutputSize{0};
    int mPass = 0, mPassCount = 1;
    // ---- the view grid ----
    ViewGrid mGrid;  // the layout and its views (view_grid.h); the focus is mState.focusedView
    std::vector<ViewCellRect> mCells;        // where the last frame put each view
    std::optional<glm::ivec2> mLinkedPixel;  // frame pixel under the cursor (a screen-space view)
    int mHoveredView = -1;
    int mDragTitle = -1;                     // a title dragged onto another view swaps the two
    std::vector<Rect> mStripRects;           // open display strips' widget panels last frame
    // Difference views' other side (by technique id), through the same schedulers as the comparison grid.
    DifferenceRuns mDifferenceRuns{mRuns};
    DifferenceRuns::Run mSelfRun;
    double mGridMilliseconds = 0.0;  // CPU time drawViewGrid took last frame
    double mUiMilliseconds = 0.0;    // CPU time of building the whole frame's UI (before its draw calls)
    glm::vec2 mHoverDrawn{-1.0f};    // the mouse position the widgets saw last frame
    // markersFor answers by intermediate id, for one pixel of the current run.
    std::map<std::string, std::pair<glm::ivec2, std::optional<std::vector<viz::ViewMarker>>>> mMarkerCache;
    bool mDirty = true;
    bool mRendering = false;  // a GPU run is about to block the thread
    double mLastRunSeconds = 0.0;
    bool mReduced = false;  // the last GPU run was at half size during an interaction

    // What the frame is drawn into: draw lists, images, clickable and named rectangles (frame_canvas.h).
    FrameCanvas mCanvas;
    ComparisonGrid mComparison{mRuns};  // G
    std::unique_ptr<viz::ui::Context> mUi;   // the widgets
    viz::ui::Input mUiInput;                 // keys, text and wheel gathered since the last frame
    Rect mParamsRect;                        // the widget panel's area last frame
    RayInspector mInspector;  // the ray inspector's pixel, if any (ray_inspector.h)
    std::optional<glm::ivec2> mPendingInspect;  // a lesson step's pixel, inspected when its result is in
    std::unique_ptr<LessonPlayer> mLesson;      // the lesson panel, when a lesson is open
    glm::ivec2 mLessonSize{0};                  // --size given with a lesson: every step at that size
    std::vector<TimelineSegment> mTimeline;  // the stepping timeline as drawn last
    Rect mTimelineRect;
    bool mDragTimeline = false;
    std::optional<std::string> mPendingScene;  // picked in the panel, loaded by loadPendingScene
    SceneFileWatch mSceneWatch;                // the scene file, when the scene is one
    bool mTextTab = false, mTextEnter = false;  // Tab / Enter pressed in a text field this frame
    ParameterPanel mPanel;  // the scene and parameter panel's own state: its sliders, lists and path field
    int mDragView = -1;                      // the view a drag pans
    int mDragOrbit = -1;                     // the orbit view a drag turns
    bool mShowGizmo = true;                   // L: the light gizmo over the frame views
    std::optional<GizmoDrag> mGizmoDrag;       // the light handle being dragged
    std::vector<Rect> mDividerRects;          // the grid's splitters last frame
    std::optional<SplitAxis> mCursorAxis;     // the resize cursor shown (none: the arrow)
    GLFWcursor* mArrowCursor = nullptr;       // stays null: the default cursor
    GLFWcursor* mColumnCursor = nullptr;      // created on first use, destroyed with the app
    GLFWcursor* mRowCursor = nullptr;
    int mFramesDrawn = 0;
    Rect mViewArea;
    float mImageHeight = 1.0f;
    glm::vec2 mHover{-1.0f};
    glm::vec2 mLastCursor{0.0f};
    int mDragButton = -1;
};

}  // namespace airlight
