#include "input_table.h"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace airlight {

namespace {

KeyBinding row(std::vector<int> keys, Command command, Command shifted, KeyContext context, HelpLine line,
               std::string label, std::string brief, std::string help) {
    KeyBinding b;
    b.keys = std::move(keys);
    b.command = command;
    b.shifted = shifted;
    b.context = context;
    b.line = line;
    b.label = std::move(label);
    b.brief = std::move(brief);
    b.help = std::move(help);
    return b;
}

KeyBinding pointer(KeyContext context, HelpLine line, std::string label, std::string brief, std::string help) {
    return row({}, Command::Pointer, Command::None, context, line, std::move(label), std::move(brief), std::move(help));
}

std::vector<KeyBinding> makeTable() {
    using C = Command;
    using X = KeyContext;
    using H = HelpLine;
    std::vector<KeyBinding> t;
    const auto add = [&](KeyBinding b) -> KeyBinding& { return t.emplace_back(std::move(b)); };

    // The frame: technique, stepping, exposure, camera.
    add(row({GLFW_KEY_TAB}, C::NextTechnique, C::PrevTechnique, X::Any, H::Frame, "`Tab` / `Shift+Tab`",
            "Tab/Shift+Tab or 1-9 technique", "the next / previous technique"))
        .repeats = true;
    add(row({GLFW_KEY_1, GLFW_KEY_2, GLFW_KEY_3, GLFW_KEY_4, GLFW_KEY_5, GLFW_KEY_6, GLFW_KEY_7, GLFW_KEY_8, GLFW_KEY_9},
            C::PickTechnique, C::PickTechnique, X::Any, H::None, "`1` ... `9`", "",
            "the technique at that place in the sidebar"))
        .repeats = true;
    add(row({GLFW_KEY_S}, C::NextStage, C::PrevStage, X::Orbit, H::Frame, "`S` / `Shift+S`", "S/Shift+S stage",
            "stop after the next / previous stage, wrapping (from the complete frame: the first stage)"))
        .repeats = true;
    add(row({GLFW_KEY_D}, C::NextSubstep, C::PrevSubstep, X::Orbit, H::Frame, "`D` / `Shift+D`",
            "D/Shift+D sub-step", "the next / previous sub-step of the stage stopped at"))
        .repeats = true;
    add(row({GLFW_KEY_HOME}, C::FirstSubstep, C::FirstSubstep, X::Any, H::Frame, "`Home` / `End`", "Home/End",
            "the first / last sub-step of the stage stopped at"))
        .backKeys = {GLFW_KEY_END};
    t.back().shifted = C::LastSubstep;
    t.back().repeats = true;
    t.back().sameWithShift = true;
    {
        KeyBinding& b = add(row({GLFW_KEY_RIGHT_BRACKET}, C::NextView, C::PrevView, X::Any, H::Frame, "`]` / `[`",
                                "[ ] view", "the focused view shows the next / previous entry of the Views list"));
        b.backKeys = {GLFW_KEY_LEFT_BRACKET};
        b.sameWithShift = true;
        b.repeats = true;
    }
    add(row({GLFW_KEY_V}, C::NextView, C::PrevView, X::Any, H::None, "`V` / `Shift+V`", "", "as `]` / `[`")).repeats =
        true;
    {
        KeyBinding& b = add(row({GLFW_KEY_PERIOD}, C::NextLayer, C::PrevLayer, X::Any, H::Frame, "`.` / `,`",
                                ", . layer", "the focused view's next / previous layer (array layer, cube face, VPL)"));
        b.backKeys = {GLFW_KEY_COMMA};
        b.sameWithShift = true;
        b.repeats = true;
    }
    {
        KeyBinding& b = add(row({}, C::ExposureUp, C::ExposureDown, X::Any, H::Frame, "`+` / `-`",
                                "+/- exposure (X auto)", "exposure up / down by a third of a stop"));
        b.chars = "+=";
        b.backChars = "-_";
    }
    add(row({GLFW_KEY_X}, C::AutoExposure, C::None, X::Any, H::None, "`X`", "", "automatic exposure again"));
    add(row({GLFW_KEY_C}, C::ToggleCameraMode, C::None, X::Orbit, H::Frame, "`C`", "C fly",
            "switch to the fly camera"));
    add(row({GLFW_KEY_C}, C::ToggleCameraMode, C::None, X::Fly, H::Frame, "`C`", "C orbit",
            "switch to the orbit camera"));
    add(row({GLFW_KEY_R}, C::ResetCamera, C::None, X::Any, H::Frame, "`R`", "R reset", "reset the camera"));
    add(row({GLFW_KEY_P}, C::PlayPause, C::None, X::Any, H::Frame, "`P`", "P play/pause",
            "play / pause the light's orbit animation (the views list gains `L_air change per frame`; the comparison "
            "grid plays too)"));
    add(pointer(X::Orbit, H::Frame, "left drag", "left drag orbit",
                "turn the camera round its target (in an orbit view such as polyvol's light volume: turn that view)"));
    add(pointer(X::Orbit, H::Frame, "wheel", "wheel zoom",
                "move the camera towards its target over the final frame; over another view, zoom the view"));
    add(pointer(X::Orbit, H::Frame, "right / middle drag", "right/middle drag pan", "pan the camera"));
    add(pointer(X::Fly, H::Frame, "right drag", "right drag look", "turn the camera where it stands"));
    {
        KeyBinding& b = add(row({GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E}, C::FlyMove,
                                C::FlyMove, X::Fly, H::Frame, "`W` `A` `S` `D` `Q` `E`",
                                "WASD move, Q/E down/up, Shift faster",
                                "move the camera forward, left, back, right, down, up while held (Shift: 4x faster); "
                                "nothing else"));
        b.repeats = true;
    }
    add(pointer(X::Fly, H::Frame, "middle drag", "middle drag pan", "pan the camera"));
    {
        KeyBinding& b = add(row({GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD}, C::UiScaleUp, C::UiScaleUp, X::Any, H::None,
                                "`Ctrl+=` / `Ctrl+-`", "", "UI scale up / down (x1.25 a step, 0.5 to 4; also --ui-scale)"));
        b.backKeys = {GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT};
        b.shifted = C::UiScaleDown;
        b.sameWithShift = true;
        b.ctrl = true;
        b.repeats = true;
    }
    add(row({GLFW_KEY_F11}, C::ToggleFullscreen, C::None, X::Any, H::None, "`F11`", "",
            "full screen on the primary monitor, and back"));
    add(row({GLFW_KEY_ESCAPE}, C::Quit, C::Quit, X::Any, H::Frame, "`Esc`", "Esc quit",
            "quit (the session is saved)"));

    // The view grid.
    add(pointer(X::Any, H::Views, "click a view", "views: click to focus", "focus it (highlighted title)"));
    add(row({GLFW_KEY_H}, C::SplitBeside, C::SplitBeside, X::Any, H::Views, "`H` / `J`", "H / J split",
            "split the focused view: a new view beside it / below it, showing the next entry of the list"))
        .backKeys = {GLFW_KEY_J};
    t.back().shifted = C::SplitBelow;
    t.back().sameWithShift = true;
    add(pointer(X::Any, H::Views, "drag a gap", "drag a gap: resize",
                "the gap between two views moves their split (each side keeps at least 5 %)"));
    add(row({GLFW_KEY_K}, C::CloseView, C::None, X::Any, H::Views, "`K`", "K close",
            "close the focused view (the last one stays)"));
    add(row({GLFW_KEY_M}, C::Maximise, C::None, X::Any, H::Views, "`M`", "M maximise",
            "maximise the focused view over the grid, and back"));
    add(row({GLFW_KEY_O}, C::SwapNext, C::SwapPrev, X::Any, H::Views, "`O` / `Shift+O`", "O swap (or drag a title)",
            "swap the focused view with the next / previous one (or drag a title onto another view)"));
    add(row({GLFW_KEY_N}, C::FocusNext, C::FocusPrev, X::Any, H::Views, "`N` / `Shift+N`", "N next",
            "focus the next / previous view"));
    add(row({GLFW_KEY_F}, C::ToggleDifference, C::None, X::Any, H::Views, "`F`", "F difference",
            "difference mode on the focused view (final frame or L_air) against the reference, and off"));
    add(row({GLFW_KEY_0}, C::FitView, C::None, X::Any, H::Views, "`0`", "0 fit",
            "fit the focused view (undo its zoom and pan)"));
    add(row({GLFW_KEY_L}, C::ToggleGizmo, C::None, X::Any, H::Views, "`L`", "L light gizmo",
            "the light gizmo over the final frame and L_air, and off"));
    add(row({GLFW_KEY_I}, C::InspectPixel, C::None, X::Any, H::Views, "`I`", "I inspect",
            "the ray inspector on the frame pixel under the cursor"));
    add(row({GLFW_KEY_G}, C::ToggleComparison, C::None, X::Any, H::Views, "`G`", "G compare",
            "every technique's L_air side by side, with times and errors, and back"));
    add(row({GLFW_KEY_E}, C::ExportView, C::None, X::Orbit, H::Views, "`E`", "E export",
            "export the focused view as EXR (values) and PNG (as shown); while `P` plays: start recording the "
            "focused view, and again (or `P`) to stop and write an animated GIF of the frames it saw, as shown, at the "
            "animation's rate (at most 600 frames or 512 MiB of them)"));
    add(row({GLFW_KEY_F12}, C::ExportWindow, C::None, X::Any, H::Views, "`F12`", "F12 window",
            "export the window as PNG"));
    add(row({GLFW_KEY_F5}, C::SaveSession, C::None, X::Any, H::Views, "`F5` / `F9`", "F5/F9 save/load session",
            "save / load the session file"))
        .backKeys = {GLFW_KEY_F9};
    t.back().shifted = C::LoadSession;
    t.back().sameWithShift = true;
    add(pointer(X::Any, H::Views, "`display +` in a title", "'display +': controls",
                "the view's display strip: channel, range, log scale, colour map, histogram, difference"));

    // The lesson player (the panel lists its own keys).
    add(row({GLFW_KEY_PAGE_UP, GLFW_KEY_PAGE_DOWN}, C::LessonKey, C::LessonKey, X::Lesson, H::None,
            "`PageUp` / `PageDown`", "", "the previous / next step"))
        .repeats = true;
    add(row({GLFW_KEY_T}, C::LessonKey, C::LessonKey, X::Lesson, H::None, "`T`", "",
            "try-it mode on / off (change anything; the step is kept)"))
        .repeats = true;
    add(row({GLFW_KEY_B}, C::LessonKey, C::LessonKey, X::Lesson, H::None, "`B`", "",
            "back to the step exactly as written"))
        .repeats = true;
    add(row({GLFW_KEY_SPACE}, C::LessonKey, C::LessonKey, X::Lesson, H::None, "`Space`", "",
            "pause / replay the step's animation (when it has one)"))
        .repeats = true;
    add(row({}, C::None, C::None, X::Text, H::None, "any key", "",
            "goes to the field (`Home` / `End`: its start / end; `Enter` or `Esc` ends the editing); no shortcut fires"));
    return t;
}

bool applies(KeyContext context, const KeyState& s) {
    switch (context) {
        case KeyContext::Any: return true;
        case KeyContext::Orbit: return !s.fly;
        case KeyContext::Fly: return s.fly;
        case KeyContext::Lesson: return s.lesson;
        case KeyContext::Text: return s.text;
    }
    return false;
}

// Which binding wins when two apply to one key: the lesson's, then the camera mode's, then any.
int precedence(KeyContext context) {
    switch (context) {
        case KeyContext::Text: case KeyContext::Lesson: return 0;
        case KeyContext::Fly: case KeyContext::Orbit: return 1;
        case KeyContext::Any: return 2;
    }
    return 3;
}

std::string contextName(KeyContext c) {
    switch (c) {
        case KeyContext::Any: return "anywhere";
        case KeyContext::Orbit: return "orbit camera";
        case KeyContext::Fly: return "fly camera";
        case KeyContext::Lesson: return "lesson open";
        case KeyContext::Text: return "text field being edited";
    }
    return "";
}

// The `index`-th key named in back quotes in a binding's label ("`S` / `Shift+S`": 0 "S", 1 "Shift+S").
std::string labelKey(const std::string& label, int index) {
    std::size_t at = 0;
    for (int i = 0;; ++i) {
        const std::size_t open = label.find('`', at);
        const std::size_t close = open == std::string::npos ? open : label.find('`', open + 1);
        if (close == std::string::npos) return "";
        if (i == index) return label.substr(open + 1, close - open - 1);
        at = close + 1;
    }
}

}  // namespace

const std::vector<KeyBinding>& keyBindings() {
    static const std::vector<KeyBinding> table = makeTable();
    return table;
}

Command commandForKey(int key, bool shift, bool repeat, const KeyState& state, int* offset) {
    if (state.text) return Command::None;  // the field being edited takes every key
    const KeyBinding* best = nullptr;
    Command command = Command::None;
    int index = 0;
    for (const KeyBinding& b : keyBindings()) {
        if (!applies(b.context, state) || b.ctrl != state.ctrl ||
            (best && precedence(b.context) >= precedence(best->context)))
            continue;
        const auto k = std::find(b.keys.begin(), b.keys.end(), key);
        const bool back = std::find(b.backKeys.begin(), b.backKeys.end(), key) != b.backKeys.end();
        if (k == b.keys.end() && !back) continue;
        best = &b;
        index = k != b.keys.end() ? int(k - b.keys.begin()) : 0;
        command = back ? b.shifted : (shift && !b.sameWithShift ? b.shifted : b.command);
    }
    if (!best || (repeat && !best->repeats)) return Command::None;
    if (offset) *offset = index;
    return command;
}

Command commandForChar(unsigned codepoint) {
    if (codepoint == 0 || codepoint > 0x7f) return Command::None;
    const char c = char(codepoint);
    for (const KeyBinding& b : keyBindings()) {
        if (b.chars.find(c) != std::string::npos) return b.command;
        if (b.backChars.find(c) != std::string::npos) return b.shifted;
    }
    return Command::None;
}

std::vector<std::string> helpBriefs(HelpLine line, bool fly) {
    std::vector<std::string> out;
    const KeyState state{fly, false};
    for (const KeyBinding& b : keyBindings())
        if (b.line == line && !b.brief.empty() && b.context != KeyContext::Lesson && applies(b.context, state))
            out.push_back(b.brief);
    return out;
}

std::string keyNames(const std::vector<Command>& commands, const KeyState& state) {
    std::string out;
    for (const Command c : commands) {
        // The binding the key handler would dispatch to for one of the command's keys, where it applies.
        for (const KeyBinding& b : keyBindings()) {
            if ((b.command != c && b.shifted != c) || !applies(b.context, state) || b.keys.empty()) continue;
            const int key = b.command == c || b.backKeys.empty() ? b.keys.front() : b.backKeys.front();
            if (commandForKey(key, b.command != c && b.backKeys.empty(), false, state) != c) continue;
            const std::string name = labelKey(b.label, b.command == c ? 0 : 1);
            if (!name.empty()) out += (out.empty() ? "" : ", ") + name;
            break;
        }
    }
    return out;
}

std::string markdownKeyTable() {
    std::string out = "| keys | where | what it does |\n| --- | --- | --- |\n";
    for (const KeyBinding& b : keyBindings()) out += "| " + b.label + " | " + contextName(b.context) + " | " + b.help + " |\n";
    return out;
}

std::string plainKeyTable() {
    std::string out;
    for (const KeyBinding& b : keyBindings()) {
        std::string label;
        for (char c : b.label)
            if (c != '`') label += c;
        std::string help;
        for (char c : b.help)
            if (c != '`') help += c;
        const std::string where = b.context == KeyContext::Any ? "" : " (" + contextName(b.context) + ")";
        out += "  " + label + where + ": " + help + "\n";
    }
    return out;
}

}  // namespace airlight
