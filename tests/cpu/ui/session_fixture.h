// A session with a view grid for the tests of the session file and the grid: three views in a split
// layout, one maximised and one focused, with display settings away from their defaults (a manual
// range, a log scale, an open strip, a relative difference against raymarch).
#pragma once

#include "session_state.h"

namespace airlight {

inline SessionState sessionWithGrid() {
    SessionState s;
    s.scene = "grate";
    s.technique = "minmax";
    s.layout = "x(0.4,0,y(0.5,3,1))";
    s.focusedView = 3;
    s.maximisedView = 1;
    SessionState::GridView a;
    a.id = 0;
    a.content = "final";
    SessionState::GridView b;
    b.id = 3;
    b.content = "minmax.rectified";
    b.layer = 2;
    b.zoom = 8.0;
    b.center = {0.25, 0.625};
    b.channel = 5, b.range = 3, b.colourMap = 2, b.difference = 0;
    b.manualMin = -0.5f, b.manualMax = 2.25f;
    b.markNegative = 1, b.logScale = true, b.stripOpen = true;
    SessionState::GridView c;
    c.id = 1;
    c.content = "airlight";
    c.difference = 3;
    c.against = "raymarch";
    c.markNegative = 0;
    s.gridViews = {a, b, c};
    return s;
}

}  // namespace airlight
