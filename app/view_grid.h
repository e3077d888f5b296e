// The window's grid of views as data: the layout of its splits (view_layout.h), each view's state by the
// layout's number, the next free number, and whether a lesson step laid it out. Its arrangements (the
// default pair, a lesson step's, a session's, a split, a close, a swap) are plain operations tested
// without a window. Which view has the focus is the window's (HeldState::focusedView): the operations
// take it and say which view should have it next.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "session_state.h"
#include "view_layout.h"
#include "view_state.h"

namespace airlight {

struct ViewGrid {
    ViewLayout layout{0};
    std::map<int, ViewState> views;  // by the layout's view number
    int nextView = 0;                // the number a new view gets
    bool lessonGrid = false;         // laid out by a lesson step (lesson()), not by the user

    // The final frame on the left, `content` (L_air when empty) on the right. Returns the view to focus:
    // the right one.
    int reset(const std::string& content);
    // A lesson step's two or three views beside the final frame: two in three columns (as tall as the
    // frame-shaped cells of the usual pair), three in a 2 x 2 grid; a fourth and later are left out.
    // Returns the view to focus: the step's first.
    int lesson(const std::vector<std::string>& contents);
    // The session's grid (its layout, each view's content, layer, pan, zoom and display settings, the
    // maximised view), or, for a session that has none, the default pair around its view with that
    // view's pan and zoom. A layout that does not parse throws std::runtime_error and leaves the grid as
    // it was. Returns the view to focus: the session's, when the layout has it.
    int restore(const SessionState& session);
    // H / J: a new view beside / below `focused` (the layout leaves a maximised view first). Returns its
    // number, or -1 when `focused` is not in the grid.
    int split(int focused, SplitAxis axis);
    // K: closes `focused`. Returns the view to focus next, or -1 (nothing closed) for the last view.
    int close(int focused);
    // O / Shift+O: `focused` trades places with the view `step` after it in reading order.
    void swap(int focused, int step);
};

}  // namespace airlight
