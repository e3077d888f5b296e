// Motion paths: the camera or the first light moving over a sequence of frames, for temporal error
// figures and exported animations. A path is a small declarative text (`camera-orbit:30deg`,
// `light-sweep:20deg`, several joined by commas) or a JSON file of keyframes. Frame i of N is a pure
// function of the path, the scene it starts from, i and N: no clock and no state carried from frame to
// frame, so two runs give the same cameras and lights bit for bit and any frame can be rendered alone
// (a reference frame can be cached by path, i and N).
//
// The motions (frame i of N; A an angle given as 30deg or 0.5rad, D a distance):
//   camera-orbit[:A]   the camera turns about the vertical (+Y) axis through its orbit target
//                      (scene/orbit_target.h) by A * i / N, forward and up turning with it; default 360deg,
//                      a full turn whose frames loop without repeating one
//   camera-dolly:D     the camera moves along its view direction by D * (1 - cos(2 pi i / N)) / 2: in to D
//                      and back out, looping; D in scene units, or P% of the distance to the orbit target
//   light-orbit[:A]    the first light travels A * i / N along the window's orbit animation (P; the cone of
//                      scene/light_orbit.h about its aim point); default 360deg, one full turn
//   light-sweep:A      the first light swings back and forth about the vertical axis through its aim point
//                      (a directional light's direction turns) by A * sin(2 pi i / N), looping; a light on
//                      that axis (within 1 degree) swings about the camera's right axis instead
// Every motion leaves frame 0 exactly as the scene is. Motions joined by commas apply in the order given.
//
// The keyframe file (a .json path):
//   {"keyframes": [{"t": 0, "camera": {"position": [0, 2, 8], "target": [0, 1, 0], "up": [0, 1, 0]},
//                   "light": {"position": [2, 5, 0], "direction": [0, -1, 0]}},
//                  {"t": 2, ...}]}
// t: strictly increasing numbers (any unit); frame i of N sits at t_first + (t_last - t_first) * i / (N - 1),
// between two keyframes positions and targets are interpolated linearly and directions linearly then
// normalised. camera (position and target, up optional: the scene camera's up, made orthogonal to the
// view) and light (position, direction or both; the first light) are optional, but every keyframe gives
// the same members.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::scene {

enum class MotionKind { CameraOrbit, CameraDolly, LightOrbit, LightSweep };

struct Motion {
    MotionKind kind = MotionKind::CameraOrbit;
    double amount = 0.0;       // radians (orbit, sweep) or scene units (dolly)
    bool percent = false;      // dolly only: amount is a fraction of the orbit target's distance
};

struct Keyframe {
    double time = 0.0;
    std::optional<glm::dvec3> cameraPosition, cameraTarget, cameraUp;
    std::optional<glm::dvec3> lightPosition, lightDirection;
};

struct MotionPath {
    std::string text;                 // as given: the --path value or the file's path
    std::vector<Motion> motions;      // a declarative path, applied in order
    std::vector<Keyframe> keyframes;  // a keyframe file (motions is then empty)
    bool movesCamera() const;
    bool movesLight() const;
};

// The camera and the lights of one frame.
struct Pose {
    Camera camera;
    std::vector<Light> lights;
};

// Parses a --path value: MOTION[:AMOUNT][,MOTION[:AMOUNT]]..., or a path ending in .json read as a
// keyframe file. Throws InputError naming the problem ("path 'camera-orbt:30deg': unknown motion ...").
MotionPath parseMotionPath(const std::string& text);
// A keyframe file's text; `source` names it in messages.
MotionPath parseKeyframes(const std::string& json, const std::string& source);

// Frame `index` of `count` (0 <= index < count) of `path`, starting from `scene`. Throws InputError when
// the path cannot move this scene: a light motion on a scene without lights or whose first light is an
// area light, keyframes whose camera target meets its position.
Pose poseAt(const MotionPath& path, const Scene& scene, int index, int count);

// Sets the scene's camera and lights to the pose's.
void applyPose(const Pose& pose, Scene& scene);

// "camera orbit 30 deg, light sweep +-20 deg" or "keyframes from FILE (3 keys)".
std::string describeMotionPath(const MotionPath& path);

}  // namespace viz::scene
