// Plays a window script (ui_script.h) a frame at a time: which action runs now, how long it waits, and
// what it does to the window, through ScriptHost, which the window implements. A click presses on one
// frame and releases on the next (widgets click on release); a drag presses, moves a quarter of the way on
// each of four frames and releases; a widget a script names is scrolled into view first, as a user would.
// Tests drive it with a recording host (tests/cpu/ui/script_player_test.cpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ui/text_renderer.h"
#include "ui_script.h"

namespace airlight {

class ScriptHost {
public:
    virtual ~ScriptHost() = default;
    // Where something a script names was drawn last frame (a widget's, a view's or a named rectangle);
    // nothing when it is not on screen. `known`: every name there is, for the error.
    virtual std::optional<viz::ui::Rect> scriptRect(const std::string& name) const = 0;
    virtual std::string knownNames() const = 0;
    // Whether `name` is one of the widgets' (which may be scrolled out of view), and scrolling it in.
    virtual bool isWidget(const std::string& name) const = 0;
    virtual void revealWidget(const std::string& name) = 0;

    virtual void pressKey(int key, int modifiers) = 0;
    virtual void typeText(const std::string& text) = 0;
    virtual void dropFile(const std::string& path) = 0;
    // The mouse: moved there without a button (hover), moved with the button held (a drag's steps), the
    // left button pressed or released there, the wheel turned where it is.
    virtual void hoverAt(glm::vec2 p) = 0;
    virtual void dragTo(glm::vec2 p) = 0;
    virtual void leftButton(bool press, glm::vec2 p) = 0;
    virtual void wheel(float notches) = 0;
    virtual void screenshot(const std::string& path, bool image) = 0;
    // Appends one stats line (process_stats.h) to `path`; false when it cannot.
    virtual bool appendStats(const std::string& path) = 0;
};

class ScriptPlayer {
public:
    // `path` names the script in errors ("PATH:LINE: ...").
    ScriptPlayer(std::vector<ScriptAction> script, std::string path)
        : mScript(std::move(script)), mPath(std::move(path)) {}

    bool empty() const { return mScript.empty(); }
    // Runs actions until one needs frames to pass (true) or the script is done (false). Throws InputError
    // "PATH:LINE: ..." for a name that is not on screen or stats that cannot be written.
    bool step(ScriptHost& host);

    // The key a `hold` keeps down (-1: none), and whether with Shift.
    int heldKey() const { return mHeld; }
    bool heldShift() const { return mHeldShift; }
    // The left button as the script holds it (pressed, or released this frame); nothing when the script
    // does not hold it (the real button counts).
    std::optional<bool> leftButtonDown() const { return mDown; }

private:
    viz::ui::Rect target(const ScriptHost& host, const ScriptAction& a, const std::string& name) const;
    // A widget named by the action is scrolled into view first: true while that takes frames.
    bool revealing(ScriptHost& host, const ScriptAction& a);

    std::vector<ScriptAction> mScript;
    std::string mPath;
    std::size_t mIndex = 0;
    int mWait = 0;           // frames left of a `frames` or `hold`
    int mRevealFrames = 0;   // frames left until a widget scrolled into view is known where it is
    int mHeld = -1;
    bool mHeldShift = false;
    int mDragStep = 0;       // 0 before the press, 1-4 moving, 5 release
    glm::vec2 mDragFrom{0.0f}, mDragTo{0.0f}, mClickPoint{0.0f};
    std::optional<bool> mDown;
};

}  // namespace airlight
