#include "script_player.h"

#include "core/error.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace airlight {

viz::ui::Rect ScriptPlayer::target(const ScriptHost& host, const ScriptAction& a, const std::string& name) const {
    if (const std::optional<viz::ui::Rect> r = host.scriptRect(name)) return *r;
    throw viz::InputError(mPath + ":" + std::to_string(a.line) + ": nothing named '" + name +
                          "' is on screen (on screen: " + host.knownNames() + ")");
}

bool ScriptPlayer::revealing(ScriptHost& host, const ScriptAction& a) {
    if (mRevealFrames > 0) return --mRevealFrames > 0;  // 0: revealed, go on
    if (!host.isWidget(a.target)) return false;
    host.revealWidget(a.target);
    // The request is served on the next frame and the new rectangle known the frame after.
    mRevealFrames = 2;
    return true;
}

bool ScriptPlayer::step(ScriptHost& host) {
    while (mIndex < mScript.size()) {
        const ScriptAction& a = mScript[mIndex];
        switch (a.kind) {
            case ScriptAction::Kind::Frames:
                if (mWait == 0) mWait = a.frames;
                if (--mWait > 0) return true;
                ++mIndex;
                return true;
            case ScriptAction::Kind::Key:
                host.pressKey(scriptKeyCode(a.target), a.modifiers);
                ++mIndex;
                return true;
            case ScriptAction::Kind::Hold:
                if (mWait == 0) {
                    host.pressKey(scriptKeyCode(a.target), a.modifiers);
                    mHeld = scriptKeyCode(a.target);
                    mHeldShift = (a.modifiers & GLFW_MOD_SHIFT) != 0;
                    mWait = a.frames + 1;
                }
                if (--mWait > 0) return true;
                mHeld = -1;
                ++mIndex;
                return true;
            case ScriptAction::Kind::Hover: {
                if (revealing(host, a)) return true;
                const viz::ui::Rect r = target(host, a, a.target);
                host.hoverAt(r.min + a.fraction * r.size());
                ++mIndex;
                return true;
            }
            case ScriptAction::Kind::Wheel: {
                if (revealing(host, a)) return true;
                const viz::ui::Rect r = target(host, a, a.target);
                host.hoverAt(r.min + 0.5f * r.size());
                host.wheel(a.notches);
                ++mIndex;
                return true;
            }
            case ScriptAction::Kind::Screenshot:
            case ScriptAction::Kind::Sidecar:
                host.screenshot(a.target, a.kind == ScriptAction::Kind::Screenshot);
                ++mIndex;
                break;
            case ScriptAction::Kind::Type:
                host.typeText(a.target);
                ++mIndex;
                return true;
            case ScriptAction::Kind::Drop:
                host.dropFile(a.target);
                ++mIndex;
                return true;
            case ScriptAction::Kind::Stats:
                if (!host.appendStats(a.target))
                    throw viz::InputError(mPath + ":" + std::to_string(a.line) + ": cannot append to '" + a.target + "'");
                ++mIndex;
                break;
            case ScriptAction::Kind::Drag: {
                // Frame 1: press at the start; frames 2-5: move a quarter of the way each; then release.
                // Both ends are fixed at the press: what is dragged (a divider, a handle) moves.
                if (mDragStep == 0) {
                    const viz::ui::Rect r = target(host, a, a.target);
                    const viz::ui::Rect onto = a.onto.empty() ? r : target(host, a, a.onto);
                    mDragFrom = r.min + a.fraction * r.size();
                    mDragTo = onto.min + a.to * onto.size();
                    host.hoverAt(mDragFrom);
                    mDown = true;  // widgets (a splitter, a slider) see the button held
                    host.leftButton(true, mDragFrom);
                    mDragStep = 1;
                } else if (mDragStep <= 4) {
                    host.dragTo(mDragFrom + (mDragTo - mDragFrom) * (float(mDragStep) / 4.0f));
                    ++mDragStep;
                } else {
                    mDown.reset();
                    host.leftButton(false, mDragTo);
                    mDragStep = 0;
                    ++mIndex;
                }
                return true;
            }
            case ScriptAction::Kind::Click: {
                // Frame 1: move there and press; frame 2: release (widgets click on release).
                if (!mDown) {
                    if (revealing(host, a)) return true;
                    const viz::ui::Rect r = target(host, a, a.target);
                    mClickPoint = r.min + a.fraction * r.size();
                    host.hoverAt(mClickPoint);
                    mDown = true;
                    host.leftButton(true, mClickPoint);
                } else {
                    host.hoverAt(mClickPoint);
                    mDown = false;
                    host.leftButton(false, mClickPoint);
                    mDown.reset();
                    ++mIndex;
                }
                return true;
            }
        }
    }
    return false;
}

}  // namespace airlight
