// Immediate-mode widgets. Each widget call lays itself out, draws into the frame's DrawList and returns
// what the user did with it this frame; the caller owns the values. What must survive between frames
// (which widget is pressed, focused, open, scrolled) lives in the Context, keyed by an Id hashed from
// the ID stack and the widget's label ("Size##light" shows "Size", identifies as "Size##light").
//   hot     = under the mouse and clickable this frame
//   active  = pressed (mouse held since the press started on it) or being dragged
//   focused = receives keyboard input (Tab / Shift+Tab cycle it, Enter or Space press a focused button)
// CPU only: Input is plain data, so tests drive the UI with synthetic frames and check results and
// the recorded widget rectangles. Coordinates: window pixels, origin top-left, y down.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "ui/theme.h"
#include "ui/text_renderer.h"

namespace viz::ui {

enum class Key { Tab, Enter, Escape, Space, Left, Right, Up, Down, Backspace, Delete, Home, End, F1, F2, F3,
                 F4, F5, F6, F7, F8, F9, F10, F11, F12, PageUp, PageDown };

struct Input {
    glm::vec2 mouse{-1.0f};    // -1: outside the window
    bool mouseDown = false;    // primary button held
    float wheel = 0.0f;        // lines scrolled this frame, + = away from the user (content moves down)
    std::vector<Key> keys;     // pressed this frame (auto-repeats included)
    std::string text;          // UTF-8 typed this frame
    bool shift = false, ctrl = false;
};

using Id = std::uint32_t;

struct Style {  // defaults: the one theme (ui/theme.h)
    glm::vec4 text = theme::kText;
    glm::vec4 textDim = theme::kDim;
    glm::vec4 panel = theme::kWidgetPanel;
    glm::vec4 frame = theme::kFrame;
    glm::vec4 frameHot = theme::kFrameHot;
    glm::vec4 frameActive = theme::kFrameActive;
    glm::vec4 accent = theme::kWidgetAccent;
    glm::vec4 focusRing = theme::kFocusRing;
};

class Context {
public:
    explicit Context(const FontAtlas& font);

    // scale: HiDPI factor (1 on a standard display); every size in the style grows with it.
    void beginFrame(const Input& input, glm::vec2 displaySize, float scale = 1.0f);
    // Resolves focus changes asked for by Tab this frame and moves popups and tooltips on top.
    void endFrame();
    // Everything drawn this frame, popups and tooltips last (one draw call with TextRenderer).
    const DrawList& drawList() const { return mDraw; }

    // ---- identity ----
    Id idOf(std::string_view label) const;
    void pushId(std::string_view scope);
    void pushId(int scope);
    void popId();

    // ---- layout: a panel stacks rows top to bottom; content taller than the panel scrolls ----
    void beginPanel(std::string_view title, const Rect& area);
    void endPanel();
    // The next row's rectangle in the current panel (full width), advancing the cursor.
    Rect row(float height);
    float rowHeight() const;  // the standard widget height at the current scale

    // ---- widgets; each returns true when the user changed the value (or pressed the button) ----
    void label(std::string_view text, bool dim = false);
    bool button(std::string_view label);
    bool checkbox(std::string_view label, bool& value);
    bool radio(std::string_view label, int& value, int option);
    bool sliderFloat(std::string_view label, float& value, float lo, float hi, bool logarithmic = false);
    bool sliderInt(std::string_view label, int& value, int lo, int hi);
    // Dragging horizontally changes the value by `speed` per pixel (x10 with Shift: fine steps x0.1).
    bool dragFloat(std::string_view label, float& value, float speed, float lo, float hi);
    bool combo(std::string_view label, int& index, const std::vector<std::string>& items);
    bool textInput(std::string_view label, std::string& text);
    // Returns whether the section is open (clicking the header toggles it).
    bool collapsingHeader(std::string_view label, bool defaultOpen = false);
    bool tabs(std::string_view label, int& selected, const std::vector<std::string>& names);
    // A draggable divider inside `area`; fraction in [0.05, 0.95] of the width (vertical divider) or height.
    bool splitter(std::string_view label, const Rect& area, bool verticalDivider, float& fraction);
    // Shown next to the mouse when the previous widget has been hovered for a moment (0.5 s).
    void tooltip(std::string_view text);
    // Shown next to the mouse this frame, one row per line, over everything (a title elided to fit shows
    // its full text while hovered).
    void tooltipNow(const std::vector<std::string>& lines);

    // ---- keyboard ----
    // True when `key` was pressed this frame (with Ctrl if asked) and no text input holds the focus.
    bool shortcut(Key key, bool ctrl = false) const;

    // ---- state, for tests and automation ----
    Id hot() const { return mHot; }
    Id active() const { return mActive; }
    Id focused() const { return mFocused; }
    // A text input held the keyboard last frame (editing keys such as Home and End are its).
    bool textFocused() const { return mTextFocus; }
    const Rect& lastRect() const { return mLastRect; }
    Id lastId() const { return mLastId; }
    // The rectangle of every widget drawn this frame, by its full label (automation clicks at names).
    const std::map<std::string, Rect>& widgetRects() const { return mRects; }
    // Scrolls the panel holding the widget `label` so the widget is in view (on the next frame's pass;
    // its new rectangle is known the frame after). For automation and keyboard focus.
    void reveal(std::string label) { mReveal = std::move(label); }
    const Style& style() const { return mStyle; }
    Style& style() { return mStyle; }
    // Seconds since beginFrame was first called with time (tooltips); tests advance it explicitly.
    void setTime(double seconds) { mTime = seconds; }

private:
    struct Panel {
        Rect area;
        Id id = 0;
        float cursorY = 0.0f;  // next row's top, in content coordinates (0 = the panel's content top)
        float contentTop = 0.0f;
    };
    struct Interaction {
        bool hovered = false;    // under the mouse (and nothing else holds it)
        bool pressed = false;    // the mouse went down on it this frame
        bool held = false;       // pressed earlier and still down
        bool clicked = false;    // released over it after a press on it
        bool activated = false;  // focused and Enter or Space pressed
    };

    // Registers a widget: records its rectangle under `label`, takes part in the focus order, and
    // resolves the mouse against it.
    Interaction interact(Id id, const Rect& rect, std::string_view label, bool focusable = true);
    bool isFocused(Id id) const { return mFocused == id; }
    void drawFrame(const Rect& rect, Id id, const Interaction& in);
    void drawFocusRing(const Rect& rect);
    void drawValueAndLabel(const Rect& row, const Rect& field, float value, std::string_view label);
    static std::string_view visibleText(std::string_view label);
    float scroll(Id panel) const;
    bool keyPressed(Key key) const;

    const FontAtlas* mFont;
    DrawList mDraw;     // widgets
    DrawList mOverlay;  // popups and tooltips, appended after the widgets at endFrame()
    Style mStyle;
    Input mInput;
    bool mPreviousMouseDown = false;
    glm::vec2 mDisplay{0.0f};
    float mScale = 1.0f;
    double mTime = 0.0;

    std::vector<Id> mIdStack;
    std::vector<Panel> mPanels;
    Id mHot = 0, mHotNext = 0, mActive = 0, mFocused = 0;
    bool mActiveSeen = false;
    std::vector<Id> mFocusOrder;      // focusable widgets in call order this frame
    int mFocusStep = 0;               // +1 / -1 when Tab / Shift+Tab was pressed this frame
    bool mTextFocus = false;          // a text input held the focus last frame (shortcuts off)
    std::vector<Id> mTextInputs;      // text inputs drawn this frame
    Rect mPopupRect, mPopupNext;      // an open popup's area last frame (blocks hover below it) / this frame
    bool mInPopup = false;            // drawing a popup's items
    Rect mLastRect;
    Id mLastId = 0;
    std::map<std::string, Rect> mRects;

    std::map<Id, bool> mOpen;         // collapsing headers and combo popups
    std::map<Id, float> mScroll;      // panels
    std::string mReveal;              // a widget to scroll into view (reveal)
    std::map<Id, float> mRevealBy;    // scroll change a panel owes to reveal, applied at endPanel
    std::map<Id, std::size_t> mCaret; // text inputs: caret byte position
    Id mHoverId = 0;                  // tooltip: widget hovered and since when
    double mHoverSince = 0.0;
    float mDragStartValue = 0.0f;
    glm::vec2 mDragStartMouse{0.0f};
};

}  // namespace viz::ui
