// Scripts of window actions for end-to-end UI tests and handouts (`airlight gui --script FILE`). One
// action per line; '#' starts a comment; names with spaces go in double quotes:
//   click NAME [FX FY]   press and release the left button over a widget or view, at the fraction
//                        (FX, FY) of its rectangle (default 0.5 0.5). NAME: a widget's label, a view
//                        ("final", or an intermediate id), "technique:ID" or "view:LABEL" in the sidebar
//   hover NAME [FX FY]   move the mouse there without pressing (e.g. before `key I`, the ray inspector)
//   drag NAME FX FY TX TY [ONTO]  press the left button at fraction (FX, FY) of the target, move to
//                        (TX, TY) of the same rectangle (or of ONTO's) over a few frames, release (pans
//                        a zoomed view, turns an orbit view, moves a divider or a light handle, ...)
//   wheel NAME N         turn the mouse wheel N notches (positive: away from the user, zooming in) over
//                        the centre of a view or widget
//   key NAME             press a key: Tab, Enter, Escape, Space, Left, Right, Up, Down, PageUp,
//                        PageDown, Home, End, F1-F12, 0-9,
//                        A-Z, [ and ], , and . (previous / next layer), = and -, optionally after Shift+
//                        and/or Ctrl+ (Shift+S)
//   hold NAME N          press a key and keep it down for N frames (fly mode's W A S D Q E), then
//                        release it
//   type TEXT            type TEXT (into the text field being edited; else as key characters)
//   drop PATH            drop a file on the window (as GLFW's drop callback does)
//   frames N             let N frames pass
//   screenshot PATH      write the window (PNG) and its sidecar JSON now
//   sidecar PATH         write only the sidecar JSON (PATH with .json) now
//   stats PATH           append one JSON line to PATH: frame, resident memory, open files, GL objects
//                        our wrappers own and GL errors so far (process_stats.h; the soak test)
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace airlight {

struct ScriptAction {
    enum class Kind { Click, Hover, Drag, Wheel, Key, Hold, Type, Drop, Frames, Screenshot, Sidecar, Stats };
    Kind kind = Kind::Frames;
    std::string target;          // widget / view name, key name or path
    glm::vec2 fraction{0.5f};    // click position within the target's rectangle
    glm::vec2 to{0.5f};          // drag: where the button is released, within the same rectangle or
    std::string onto;            // within this one's (drag ... ONTO), when not empty
    int frames = 1;              // frames, hold
    float notches = 0.0f;        // wheel
    int modifiers = 0;           // key: GLFW_MOD_SHIFT | GLFW_MOD_CONTROL
    int line = 0;                // 1-based, for messages
};

// Throws InputError "FILE:LINE: reason" for an unknown action, a missing or malformed argument, an
// unknown key name, or a file that cannot be read.
std::vector<ScriptAction> parseScript(const std::string& path);

// GLFW key code for a script key name, or -1.
int scriptKeyCode(const std::string& name);

}  // namespace airlight
