// The scene and parameter panel under the view grid: the built-in scene and stiff-case pickers, the path
// field that opens a glTF file, the medium, the light picker, intensity and placement, the technique's
// preset and declared parameters (never its sub-steps: those are the stepping cursor's), and the plan.
// It edits the scene's medium and lights in place and hands everything else back as edits for the window
// to carry out, so tests drive it without a window. The caller opens the panel (Context::beginPanel).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "debug/technique.h"
#include "on_off_slider.h"
#include "scene/scene.h"
#include "ui/immediate.h"

namespace airlight {

// What the user did in the panel this frame.
struct ParameterPanelEdits {
    bool sceneEdited = false;              // the medium or a light changed (in the scene passed in)
    std::optional<std::string> pickScene;  // a built-in scene or stiff case ("stiff/ID") to load
    std::optional<std::string> openFile;   // a path to open (Enter in the field, a completion, Open)
    std::vector<std::pair<std::string, double>> settings;  // parameters set (a preset's, a widget's), in order
};

// What the panel shows besides the scene.
struct ParameterPanelFacts {
    std::string sceneSource;                  // the scene's name, "stiff/ID" or a file's path
    const viz::Technique* technique = nullptr;
    const viz::Settings* settings = nullptr;  // the technique's settings as they are (defaults for the missing)
    const viz::Plan* plan = nullptr;          // the plan its section shows
    bool tab = false, enter = false;          // Tab / Enter pressed in a text field this frame
};

class ParameterPanel {
public:
    ParameterPanelEdits draw(viz::ui::Context& ui, viz::scene::Scene& scene, int& selectedLight,
                             const ParameterPanelFacts& facts);
    // Another scene or session: the on/off boxes have nothing to bring back.
    void forgetValues();

private:
    void scenePickers(viz::ui::Context& ui, const std::string& source, ParameterPanelEdits& edits);
    void openFileField(viz::ui::Context& ui, bool tab, bool enter, ParameterPanelEdits& edits);

    // Declared log ranges covering every built-in scene and stiff case (millimetre models, scales 1e-3 to
    // 1e4): a light's intensity (candela or lux) and the medium's coefficients (per scene unit).
    OnOffSlider mIntensity{1e-6f, 1e12f, 1.0}, mSigmaS{1e-7f, 1e3f, 0.1}, mSigmaA{1e-7f, 1e3f, 0.01};
    std::vector<std::string> mSceneChoices, mStiffChoices;  // built on first draw
    std::string mOpenPath;                                  // the path field's text
};

}  // namespace airlight
