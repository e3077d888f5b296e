// A technique's parameters: what each is (ParamInfo) and the values a run gets (Settings).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace viz {

struct ParamInfo {
    std::string name;  // "samples", "jitter", "shadow_map", ...
    std::string help;  // one line
    double defaultValue = 0.0;
    double minValue = 0.0;
    double maxValue = 0.0;
    bool integer = true;
    // Named values: choices[i] stands for the value i (e.g. weighting=physical); empty for plain numbers.
    std::vector<std::string> choices{};
    // A per-axis form: `name=AxBxC` sets these parameters in order (e.g. voxels -> voxels_alpha,
    // voxels_theta, voxels_phi); empty when the parameter takes one number only.
    std::vector<std::string> components{};
};

using Settings = std::map<std::string, double>;

// "name=value" as a user writes it in --set and lessons: a named value by its name (integrand=svd,
// accum=rgba8), any other value as the shortest number that reads back as it (exactNumber: 8388608, not
// %g's 8.38861e+06). Unknown names and out-of-range indices stay numbers.
std::string settingText(const std::vector<ParamInfo>& params, const std::string& name, double value);

// The controls the window drives in a technique that has them (Technique::controls()), each a set of
// parameters declared here once, with one range, for every technique.
struct Controls {
    bool pickedPixel = false;    // kPickX, kPickY (pickParam): per-pixel views follow the ray inspector's pixel
    bool orbitCamera = false;    // kOrbitYaw, kOrbitPitch, kOrbitZoom (orbitParams): orbit views turn by dragging
    bool animationTime = false;  // kAnimationTime (animationTimeParam): the animation clock moves it
};
inline constexpr const char* kPickX = "pick_x";
inline constexpr const char* kPickY = "pick_y";
inline constexpr const char* kOrbitYaw = "mesh_yaw";
inline constexpr const char* kOrbitPitch = "mesh_pitch";
inline constexpr const char* kOrbitZoom = "mesh_zoom";
inline constexpr const char* kAnimationTime = "time";

// Their values in a run request (FrameInput::controls), typed. A technique reads them only here; the names
// above are how the edges spell them (--set pick_x=60, a lesson's mesh_yaw=120, a session file), and
// takeControls moves them out of the settings into this. The defaults are the parameters' defaults.
struct FrameControls {
    int pickX = -1, pickY = -1;  // the picked pixel (column from the left, row from the top); -1: the centre
    double orbitYaw = 35.0;      // orbit views' camera: degrees about the vertical,
    double orbitPitch = 25.0;    // degrees above the horizon,
    double orbitZoom = 1.0;      // and zoom (1 fits the scene and the camera)
    double time = 0.0;           // seconds on the animation clock
};

// Moves the control names found in `settings` into the returned controls (the rest keep their defaults).
FrameControls takeControls(Settings& settings);
// The controls spelled as settings (every name), as the edges write them.
Settings controlSettings(const FrameControls& controls);

// The picked pixel a technique's per-pixel intermediates follow (the ray inspector's pixel): `axis` 'x'
// gives pick_x (column, 0 = left), 'y' pick_y (row, 0 = top); -1 is the image centre. `what` names what the
// technique shows for it.
ParamInfo pickParam(char axis, const std::string& what);

// The orbit camera of a technique's own orbit views (yaw, pitch, zoom, in that order); `when` says when it
// is used ("mesh_view").
std::vector<ParamInfo> orbitParams(const std::string& when);

// Seconds on the animation clock; `what` says what it moves.
ParamInfo animationTimeParam(const std::string& what);

// The `force_features` parameter every technique that prunes by scene offers: 1 runs every stage and
// compiles in every feature its plan would leave out for the scene, so `airlight report` can measure
// what each plan saves. The image must not change.
ParamInfo forceFeaturesParam();

}  // namespace viz
