// The interactive window: a grid of views (the final frame, L_air, intermediates; each zoomable to
// texel level, with linked cursors, display controls and difference views), a technique picker, an
// orbit/fly camera, stage and sub-step stepping, the ray inspector, the comparison grid, a scene and
// parameter panel, per-stage timing bars, export, a session file, and automation (screenshots with a
// sidecar of view rectangles, scripted actions).
#pragma once

#include <map>
#include <string>

#include "cli_args.h"
#include "debug/technique.h"
#include "scene/gltf_loader.h"
#include "ui_script.h"

namespace airlight {

struct GuiOptions {
    std::string scene;      // built-in name or .gltf/.glb path
    std::string technique;  // initial technique id; empty = the first registered one
    int width = 320;        // internal render resolution; the panes upscale it (nearest)
    int height = 240;
    // --set, per technique id: the given parameters that technique has, a named value as it declares it
    // (epipole=paper is 2 in vsv, 1 in ivsv); every name given is some technique's (settingsByTechnique).
    std::map<std::string, viz::Settings> settings;
    std::map<std::string, Refusals> settingErrors;  // per technique id: the --set values it refuses (shown on switching to it)
    viz::scene::LoadOptions load;  // for .gltf/.glb scenes (--no-default-light)
    // Automation (tests, handouts): after `frames` frames (and once a CPU technique's result is in),
    // write the window to `screenshot` (PNG) and its view rectangles to the same path with .json, then
    // exit. Empty: run until closed.
    std::string screenshot;
    int frames = 1;
    // Actions replayed one after another (ui_script.h); the window exits when they are done, after
    // writing `screenshot` if one is given.
    std::vector<ScriptAction> script;
    std::string scriptPath;
    // The session file (F5 saves, F9 loads, saved on exit except in screenshot runs); loaded at start
    // when given with --state. Command-line --scene, --technique and --set override what it holds.
    std::string statePath;
    std::string exportDir = "airlight-exports";  // E (view as EXR + PNG) and F12 (window) write here
    // A lesson's .md file: the lesson player's panel opens beside the views (lesson_player.h). With
    // sizeGiven, every step renders at width x height.
    std::string lesson;
    // --path: what P plays (a motion path, scene/motion_path.h) and the frames of its loop; empty: the
    // first light's orbit.
    std::string path;
    int pathFrames = 120;
    float uiScale = 1.0f;  // --ui-scale: times the display's content scale (Ctrl+= / Ctrl+- change it)
    bool loadStateAtStart = false;
    bool sceneGiven = false, techniqueGiven = false, sizeGiven = false;
};

// Opens the window and runs until it is closed. Throws InputError for a bad scene or technique (before
// any window opens) or when no GL 4.5 window can be created. Returns the process exit code.
int runGui(const GuiOptions& options);

}  // namespace airlight
