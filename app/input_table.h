// The window's one table of key bindings: which key does what, where. The key handler dispatches from
// it, the help lines at the bottom of the window are generated from it, and so is the README's key
// table (a test checks that the README's copy equals markdownKeyTable()).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace airlight {

// What a binding does. The window maps each command to one action (gui.cpp, GuiApp::perform).
enum class Command {
    None,            // nothing (a shifted key that has no meaning)
    Quit,
    NextTechnique, PrevTechnique, PickTechnique,  // PickTechnique: 1-9, the key's offset from the first
    NextStage, PrevStage, NextSubstep, PrevSubstep, FirstSubstep, LastSubstep,
    NextView, PrevView, NextLayer, PrevLayer, FitView,
    SplitBeside, SplitBelow, CloseView, Maximise, SwapNext, SwapPrev, FocusNext, FocusPrev,
    ToggleDifference, ToggleGizmo, InspectPixel, ToggleComparison, PlayPause,
    ExportView, ExportWindow, SaveSession, LoadSession,
    ToggleCameraMode, ResetCamera, AutoExposure, ExposureUp, ExposureDown,
    UiScaleUp, UiScaleDown, ToggleFullscreen,
    FlyMove,         // held W A S D Q E in fly mode: the frame loop reads them (documentation row)
    LessonKey,       // handed to the lesson player (which knows whether its step has an animation)
    Pointer,         // a mouse gesture: documentation row, handled by the pointer handlers
};

// Where a binding applies.
enum class KeyContext {
    Any,     // everywhere (unless a text field takes the key)
    Orbit,   // the camera is in orbit mode
    Fly,     // the camera is in fly mode
    Lesson,  // a lesson is open
    Text,    // a text field is being edited: it takes every key
};

// The help line a binding is listed on: the frame and camera line, or the view-grid line.
enum class HelpLine { Frame, Views, None };

struct KeyBinding {
    std::vector<int> keys;          // GLFW key codes (any of them); empty: characters or a pointer gesture
    std::vector<int> backKeys;      // keys for `shifted` whether or not Shift is held ("[" beside "]")
    std::string chars;              // characters (onChar) for `command`, e.g. "+=" for exposure up
    std::string backChars;          // characters for `shifted` ("-_")
    Command command = Command::None;
    Command shifted = Command::None;  // `keys` with Shift held (unless sameWithShift), and `backKeys`
    bool sameWithShift = false;       // Shift+key is `command` too
    bool repeats = false;           // a held key repeats the command
    bool ctrl = false;              // only with Ctrl held (and bindings without it only without Ctrl)
    KeyContext context = KeyContext::Any;
    HelpLine line = HelpLine::None;
    std::string label;              // as the README shows the keys: "`S` / `Shift+S`", "drag a gap"
    std::string brief;              // help-line text, short
    std::string help;               // the README's description
};

// Every binding, in the order the README lists them.
const std::vector<KeyBinding>& keyBindings();

// Where the window is when a key arrives.
struct KeyState {
    bool fly = false;         // the camera is in fly mode
    bool lesson = false;      // a lesson is open
    bool text = false;        // a text field is being edited
    bool ctrl = false;        // Ctrl is held
};

// The command for a key press, with the binding's context rules applied (a Fly binding wins in fly mode,
// so W A S D Q E drive the camera and nothing else); Command::None when nothing is bound. `offset` gets
// the key's position in a range binding (1-9: 0-8).
Command commandForKey(int key, bool shift, bool repeat, const KeyState& state, int* offset = nullptr);
// The command for a typed character (exposure + and -), or Command::None.
Command commandForChar(unsigned codepoint);

// The keys of `commands` where the window is (`state`), as the key table names them, comma-separated:
// {NextStage, NextSubstep, FirstSubstep, LastSubstep} gives "S, D, Home, End" with the orbit camera and
// "Home, End" in fly mode (S and D drive the camera there). A command without a key there is left out.
std::string keyNames(const std::vector<Command>& commands, const KeyState& state);
// The briefs of one help line at the bottom of the window (fly or orbit camera), in the table's order.
std::vector<std::string> helpBriefs(HelpLine line, bool fly);
// The README's key table (Markdown, one row per binding, with a context column).
std::string markdownKeyTable();
// The same as plain text, for `airlight gui --help`.
std::string plainKeyTable();

}  // namespace airlight
