#include "ui/immediate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/text.h"

namespace viz::ui {

namespace {

constexpr float kPadding = 4.0f;     // inside frames and between rows, at scale 1
constexpr float kRowHeight = 22.0f;  // at scale 1
constexpr float kLabelFraction = 0.38f;  // of a row's width, for the label at the right of a slider
constexpr double kTooltipDelay = 0.5;

// 32-bit FNV-1a over the bytes of a label, continuing from the enclosing scope's id; never 0 (0 = none).
Id hashBytes(std::string_view text, Id seed) {
    Id h = seed ? seed : 2166136261u;
    for (unsigned char c : text) h = (h ^ c) * 16777619u;
    return h ? h : 1u;
}

bool contains(const Rect& r, glm::vec2 p) { return r.contains(p); }

using viz::format;

// Byte position of the code point before / after `pos` in UTF-8 text.
std::size_t previousCodepoint(const std::string& text, std::size_t pos) {
    if (pos == 0) return 0;
    --pos;
    while (pos > 0 && (static_cast<unsigned char>(text[pos]) & 0xC0) == 0x80) --pos;
    return pos;
}
std::size_t nextCodepointStart(const std::string& text, std::size_t pos) {
    if (pos >= text.size()) return text.size();
    ++pos;
    while (pos < text.size() && (static_cast<unsigned char>(text[pos]) & 0xC0) == 0x80) ++pos;
    return pos;
}

}  // namespace

Context::Context(const FontAtlas& font) : mFont(&font), mDraw(font), mOverlay(font) {}

void Context::beginFrame(const Input& input, glm::vec2 displaySize, float scale) {
    mPreviousMouseDown = mInput.mouseDown;
    mInput = input;
    mDisplay = displaySize;
    mScale = std::max(scale, 0.25f);
    mDraw.clear();
    mOverlay.clear();
    mRects.clear();
    mFocusOrder.clear();
    mIdStack.clear();
    mPanels.clear();
    mHot = 0;
    mActiveSeen = false;
    mFocusStep = 0;
    for (Key k : input.keys)
        if (k == Key::Tab) mFocusStep = input.shift ? -1 : 1;
    mTextInputs.clear();
    mPopupRect = mPopupNext;
    mPopupNext = Rect{};
}

void Context::endFrame() {
    VIZ_CHECK(mPanels.empty(), "ui::Context::endFrame: a panel was not ended");
    // A widget that was pressed but is no longer drawn releases the mouse.
    if (mActive != 0 && !mActiveSeen) mActive = 0;
    // The focused widget must still exist; Tab moves the focus along this frame's order.
    const auto it = std::find(mFocusOrder.begin(), mFocusOrder.end(), mFocused);
    if (it == mFocusOrder.end()) mFocused = 0;
    if (mFocusStep != 0 && !mFocusOrder.empty()) {
        const int n = int(mFocusOrder.size());
        int i = it == mFocusOrder.end() ? (mFocusStep > 0 ? -1 : 0) : int(it - mFocusOrder.begin());
        i = ((i + mFocusStep) % n + n) % n;
        mFocused = mFocusOrder[std::size_t(i)];
    }
    mTextFocus = mFocused != 0 && std::find(mTextInputs.begin(), mTextInputs.end(), mFocused) != mTextInputs.end();
    mDraw.append(mOverlay);
}

// ---- identity ----

Id Context::idOf(std::string_view label) const {
    return hashBytes(label, mIdStack.empty() ? 0u : mIdStack.back());
}

void Context::pushId(std::string_view scope) { mIdStack.push_back(idOf(scope)); }

void Context::pushId(int scope) { pushId(std::to_string(scope)); }

void Context::popId() {
    VIZ_CHECK(!mIdStack.empty(), "ui::Context::popId without pushId");
    mIdStack.pop_back();
}

std::string_view Context::visibleText(std::string_view label) {
    const std::size_t hashes = label.find("##");
    return hashes == std::string_view::npos ? label : label.substr(0, hashes);
}

// ---- layout ----

float Context::rowHeight() const { return kRowHeight * mScale; }

void Context::beginPanel(std::string_view title, const Rect& area) {
    Panel p;
    p.area = area;
    p.id = idOf(title);
    mDraw.rect(area, mStyle.panel);
    const float pad = kPadding * mScale;
    float top = area.min.y + pad;
    if (!visibleText(title).empty()) {
        mDraw.textClipped({area.min.x + pad, top}, visibleText(title), mStyle.textDim, area.max.x - pad);
        top += mFont->lineHeight() + pad;
    }
    p.contentTop = top;
    p.cursorY = -scroll(p.id);
    mPanels.push_back(p);
    pushId(title);
    mDraw.pushClip({{area.min.x, top}, area.max});
}

void Context::endPanel() {
    VIZ_CHECK(!mPanels.empty(), "ui::Context::endPanel without beginPanel");
    mDraw.popClip();
    popId();
    const Panel p = mPanels.back();
    mPanels.pop_back();
    // Scrolling: the wheel moves the content while the mouse is over the panel, within the content.
    const float visible = p.area.max.y - p.contentTop;
    const float content = p.cursorY + scroll(p.id);
    const float maxScroll = std::max(0.0f, content - visible);
    float s = scroll(p.id);
    if (contains(p.area, mInput.mouse) && mInput.wheel != 0.0f) s -= mInput.wheel * rowHeight() * 3.0f;
    if (const auto it = mRevealBy.find(p.id); it != mRevealBy.end()) {
        s += it->second;
        mRevealBy.erase(it);
    }
    mScroll[p.id] = std::clamp(s, 0.0f, maxScroll);
    if (maxScroll > 0.0f) {
        // A thin bar shows where the view is in the content.
        const float w = 3.0f * mScale, h = visible * visible / content;
        const float y = p.contentTop + (visible - h) * mScroll[p.id] / maxScroll;
        mDraw.rect({{p.area.max.x - w - 1.0f, y}, {p.area.max.x - 1.0f, y + h}}, mStyle.frameHot);
    }
}

float Context::scroll(Id panel) const {
    const auto it = mScroll.find(panel);
    return it == mScroll.end() ? 0.0f : it->second;
}

Rect Context::row(float height) {
    VIZ_CHECK(!mPanels.empty(), "ui::Context: widgets go inside beginPanel/endPanel");
    Panel& p = mPanels.back();
    const float pad = kPadding * mScale;
    Rect r{{p.area.min.x + pad, p.contentTop + p.cursorY}, {p.area.max.x - pad, p.contentTop + p.cursorY + height}};
    p.cursorY += height + pad;
    return r;
}

// ---- interaction ----

bool Context::keyPressed(Key key) const {
    return std::find(mInput.keys.begin(), mInput.keys.end(), key) != mInput.keys.end();
}

bool Context::shortcut(Key key, bool ctrl) const { return !mTextFocus && keyPressed(key) && mInput.ctrl == ctrl; }

Context::Interaction Context::interact(Id id, const Rect& rect, std::string_view label, bool focusable) {
    Interaction in;
    mLastRect = rect;
    mLastId = id;
    if (!label.empty()) mRects[std::string(label)] = rect;
    if (!mReveal.empty() && label == mReveal && !mInPopup) {  // a popup list is placed, not scrolled
        if (!mPanels.empty()) {
            const Panel& p = mPanels.back();
            if (rect.min.y < p.contentTop) mRevealBy[p.id] = rect.min.y - p.contentTop;
            else if (rect.max.y > p.area.max.y) mRevealBy[p.id] = rect.max.y - p.area.max.y;
        }
        mReveal.clear();
    }
    if (focusable) mFocusOrder.push_back(id);
    // Hidden by scrolling (outside the panel's clip) or under last frame's open popup: not hoverable.
    bool visible = true;
    // A popup's items are drawn over everything (the overlay): they may hang below their panel.
    if (!mPanels.empty() && !mInPopup) {
        const Panel& p = mPanels.back();
        visible = mInput.mouse.y >= p.contentTop && contains(p.area, mInput.mouse);
    }
    const bool underPopup = !mInPopup && contains(mPopupRect, mInput.mouse);
    in.hovered = visible && !underPopup && contains(rect, mInput.mouse) && (mActive == 0 || mActive == id);
    if (in.hovered) mHot = id;
    const bool pressedNow = mInput.mouseDown && !mPreviousMouseDown;
    if (in.hovered && pressedNow) {
        mActive = id;
        if (focusable) mFocused = id;
        in.pressed = true;
    }
    if (mActive == id) {
        mActiveSeen = true;
        in.held = mInput.mouseDown;
        if (!mInput.mouseDown) {
            in.clicked = contains(rect, mInput.mouse);
            mActive = 0;
        }
    }
    // Keyboard: Enter or Space on the focused widget acts like a click.
    if (isFocused(id) && (keyPressed(Key::Enter) || keyPressed(Key::Space))) in.activated = true;
    return in;
}

void Context::drawFrame(const Rect& rect, Id id, const Interaction& in) {
    const glm::vec4 c = mActive == id ? mStyle.frameActive : in.hovered ? mStyle.frameHot : mStyle.frame;
    mDraw.rect(rect, c);
    if (isFocused(id)) drawFocusRing(rect);
}

void Context::drawFocusRing(const Rect& r) {
    const float w = std::max(1.0f, mScale);
    mDraw.rect({r.min, {r.max.x, r.min.y + w}}, mStyle.focusRing);
    mDraw.rect({{r.min.x, r.max.y - w}, r.max}, mStyle.focusRing);
    mDraw.rect({r.min, {r.min.x + w, r.max.y}}, mStyle.focusRing);
    mDraw.rect({{r.max.x - w, r.min.y}, r.max}, mStyle.focusRing);
}

// ---- widgets ----

void Context::label(std::string_view text, bool dim) {
    const Rect r = row(mFont->lineHeight());
    mDraw.textClipped(r.min, text, dim ? mStyle.textDim : mStyle.text, r.max.x);
    mLastRect = r;
    mLastId = 0;
}

bool Context::button(std::string_view label) {
    const Rect r = row(rowHeight());
    const Id id = idOf(label);
    const Interaction in = interact(id, r, label);
    drawFrame(r, id, in);
    const std::string_view text = visibleText(label);
    const float w = mFont->measure(text);
    mDraw.textClipped({std::max(r.min.x + kPadding * mScale, (r.min.x + r.max.x - w) * 0.5f),
                       (r.min.y + r.max.y - mFont->lineHeight()) * 0.5f},
                      text, mStyle.text, r.max.x - kPadding * mScale);
    return in.clicked || in.activated;
}

bool Context::checkbox(std::string_view label, bool& value) {
    const Rect r = row(rowHeight());
    const Id id = idOf(label);
    const Interaction in = interact(id, r, label);
    const float box = rowHeight() - 2.0f * kPadding * mScale;
    const Rect b{{r.min.x, r.min.y + kPadding * mScale}, {r.min.x + box, r.min.y + kPadding * mScale + box}};
    drawFrame(b, id, in);
    if (value) mDraw.rect({b.min + box * 0.25f, b.max - box * 0.25f}, mStyle.accent);
    mDraw.textClipped({b.max.x + kPadding * 2.0f * mScale, (r.min.y + r.max.y - mFont->lineHeight()) * 0.5f},
                      visibleText(label), mStyle.text, r.max.x);
    if (in.clicked || in.activated) {
        value = !value;
        return true;
    }
    return false;
}

bool Context::radio(std::string_view label, int& value, int option) {
    bool on = value == option;
    const bool before = on;
    pushId(option);
    const bool changed = checkbox(label, on);
    popId();
    mRects[std::string(label)] = mLastRect;
    if (changed && on && !before) {
        value = option;
        return true;
    }
    return false;  // clicking the chosen option keeps it chosen
}

// A numeric field's value centred in `field`, and the label right of it in the row `r`.
void Context::drawValueAndLabel(const Rect& r, const Rect& field, float value, std::string_view label) {
    const std::string text = format("%.4g", value);
    const float tw = mFont->measure(text);
    const float y = (r.min.y + r.max.y - mFont->lineHeight()) * 0.5f;
    mDraw.text({(field.min.x + field.max.x - tw) * 0.5f, y}, text, mStyle.text);
    mDraw.textClipped({field.max.x + kPadding * 2.0f * mScale, y}, visibleText(label), mStyle.text, r.max.x);
}

bool Context::sliderFloat(std::string_view label, float& value, float lo, float hi, bool logarithmic) {
    VIZ_CHECK(hi > lo && (!logarithmic || lo > 0.0f), "sliderFloat: bad range");
    const Rect r = row(rowHeight());
    const Id id = idOf(label);
    const float labelWidth = (r.max.x - r.min.x) * kLabelFraction;
    const Rect track{r.min, {r.max.x - labelWidth, r.max.y}};
    const Interaction in = interact(id, track, label);
    drawFrame(track, id, in);
    const auto toT = [&](float v) {
        v = std::clamp(v, lo, hi);
        return logarithmic ? std::log(v / lo) / std::log(hi / lo) : (v - lo) / (hi - lo);
    };
    const auto fromT = [&](float t) {
        t = std::clamp(t, 0.0f, 1.0f);
        return logarithmic ? lo * std::pow(hi / lo, t) : lo + t * (hi - lo);
    };
    const float old = value;
    if (in.held || in.pressed) value = fromT((mInput.mouse.x - track.min.x) / std::max(1.0f, track.max.x - track.min.x));
    if (isFocused(id)) {
        const float step = mInput.shift ? 0.001f : 0.01f;
        if (keyPressed(Key::Left)) value = fromT(toT(value) - step);
        if (keyPressed(Key::Right)) value = fromT(toT(value) + step);
        if (keyPressed(Key::Home)) value = lo;
        if (keyPressed(Key::End)) value = hi;
    }
    const float t = toT(value);
    const float x = track.min.x + t * (track.max.x - track.min.x);
    mDraw.rect({{track.min.x, track.min.y}, {x, track.max.y}}, mStyle.frameActive);
    mDraw.rect({{x - 2.0f * mScale, track.min.y}, {x + 2.0f * mScale, track.max.y}}, mStyle.accent);
    drawValueAndLabel(r, track, value, label);
    return value != old;
}

bool Context::sliderInt(std::string_view label, int& value, int lo, int hi) {
    VIZ_CHECK(hi > lo, "sliderInt: bad range");
    float f = float(value);
    const Id id = idOf(label);
    const bool focused = isFocused(id);
    // Whole steps by keyboard: one unit per arrow press, not 1% of the range.
    const bool left = focused && keyPressed(Key::Left), right = focused && keyPressed(Key::Right);
    sliderFloat(label, f, float(lo), float(hi));
    int v = int(std::lround(f));
    if (left || right) v = std::clamp(value + (right ? 1 : 0) - (left ? 1 : 0), lo, hi);
    if (v == value) return false;
    value = v;
    return true;
}

bool Context::dragFloat(std::string_view label, float& value, float speed, float lo, float hi) {
    const Rect r = row(rowHeight());
    const Id id = idOf(label);
    const float labelWidth = (r.max.x - r.min.x) * kLabelFraction;
    const Rect field{r.min, {r.max.x - labelWidth, r.max.y}};
    const Interaction in = interact(id, field, label);
    drawFrame(field, id, in);
    const float old = value;
    if (in.pressed) {
        mDragStartValue = value;
        mDragStartMouse = mInput.mouse;
    }
    if (in.held) {
        const float k = mInput.shift ? 0.1f : 1.0f;
        value = std::clamp(mDragStartValue + (mInput.mouse.x - mDragStartMouse.x) * speed * k, lo, hi);
    }
    if (isFocused(id)) {
        if (keyPressed(Key::Left)) value = std::clamp(value - speed * 10.0f, lo, hi);
        if (keyPressed(Key::Right)) value = std::clamp(value + speed * 10.0f, lo, hi);
    }
    drawValueAndLabel(r, field, value, label);
    return value != old;
}

bool Context::combo(std::string_view label, int& index, const std::vector<std::string>& items) {
    const Rect r = row(rowHeight());
    const Id id = idOf(label);
    const float labelWidth = (r.max.x - r.min.x) * kLabelFraction;
    const Rect field{r.min, {r.max.x - labelWidth, r.max.y}};
    const Interaction in = interact(id, field, label);
    drawFrame(field, id, in);
    bool& open = mOpen[id];
    if (in.clicked || in.activated) open = !open;
    const float pad = kPadding * mScale;
    const float textY = (r.min.y + r.max.y - mFont->lineHeight()) * 0.5f;
    if (index >= 0 && index < int(items.size()))
        mDraw.textClipped({field.min.x + pad, textY}, items[std::size_t(index)], mStyle.text, field.max.x - pad * 4);
    mDraw.text({field.max.x - pad - mFont->measure("v"), textY}, "v", mStyle.textDim);
    mDraw.textClipped({field.max.x + pad * 2.0f, textY}, visibleText(label), mStyle.text, r.max.x);
    if (!open) return false;

    // The list opens below the field, over everything else (overlay), and closes on a choice, on Escape
    // or on a press anywhere outside it.
    bool changed = false;
    const float h = rowHeight();
    Rect list{{field.min.x, field.max.y}, {field.max.x, field.max.y + h * float(items.size())}};
    if (list.max.y > mDisplay.y && field.min.y - h * float(items.size()) >= 0.0f)
        list = {{field.min.x, field.min.y - h * float(items.size())}, {field.max.x, field.min.y}};
    mPopupNext = list;
    mOverlay.rect(list, mStyle.panel);
    const bool pressedNow = mInput.mouseDown && !mPreviousMouseDown;
    mInPopup = true;
    pushId(label);
    for (std::size_t i = 0; i < items.size(); ++i) {
        const Rect item{{list.min.x, list.min.y + h * float(i)}, {list.max.x, list.min.y + h * float(i + 1)}};
        const Id itemId = idOf(items[i]);
        const Interaction ii = interact(itemId, item, std::string(label) + "/" + items[i], false);
        if (ii.hovered || int(i) == index) mOverlay.rect(item, ii.hovered ? mStyle.frameHot : mStyle.frame);
        mOverlay.textClipped({item.min.x + pad, item.min.y + (h - mFont->lineHeight()) * 0.5f}, items[i], mStyle.text,
                             item.max.x - pad);
        if (ii.clicked) {
            changed = int(i) != index;
            index = int(i);
            open = false;
        }
    }
    popId();
    mInPopup = false;
    if (keyPressed(Key::Escape) || (pressedNow && !contains(list, mInput.mouse) && !contains(field, mInput.mouse)))
        open = false;
    if (isFocused(id) && (keyPressed(Key::Up) || keyPressed(Key::Down)) && !items.empty()) {
        const int next = std::clamp(index + (keyPressed(Key::Down) ? 1 : -1), 0, int(items.size()) - 1);
        changed |= next != index;
        index = next;
    }
    mLastRect = field;
    mLastId = id;
    return changed;
}

bool Context::textInput(std::string_view label, std::string& text) {
    const Rect r = row(rowHeight());
    const Id id = idOf(label);
    const float labelWidth = (r.max.x - r.min.x) * kLabelFraction;
    const Rect field{r.min, {r.max.x - labelWidth, r.max.y}};
    const Interaction in = interact(id, field, label);
    mTextInputs.push_back(id);
    std::size_t& caret = mCaret[id];
    if (in.pressed) caret = text.size();
    caret = std::min(caret, text.size());
    const std::string old = text;
    if (isFocused(id)) {
        if (!mInput.text.empty()) {
            text.insert(caret, mInput.text);
            caret += mInput.text.size();
        }
        for (Key k : mInput.keys) {
            if (k == Key::Backspace && caret > 0 && mInput.ctrl) {
                // Ctrl+Backspace: back to the previous '/' or space (one folder of a path, one word).
                std::size_t start = caret;
                while (start > 0 && (text[start - 1] == '/' || text[start - 1] == ' ')) --start;
                while (start > 0 && text[start - 1] != '/' && text[start - 1] != ' ') --start;
                text.erase(start, caret - start);
                caret = start;
            } else if (k == Key::Backspace && caret > 0) {
                const std::size_t start = previousCodepoint(text, caret);
                text.erase(start, caret - start);
                caret = start;
            } else if (k == Key::Delete && caret < text.size()) {
                text.erase(caret, nextCodepointStart(text, caret) - caret);
            } else if (k == Key::Left) {
                caret = previousCodepoint(text, caret);
            } else if (k == Key::Right) {
                caret = nextCodepointStart(text, caret);
            } else if (k == Key::Home) {
                caret = 0;
            } else if (k == Key::End) {
                caret = text.size();
            } else if (k == Key::Enter || k == Key::Escape) {
                mFocused = 0;  // done editing
            }
        }
    }
    drawFrame(field, id, in);
    const float pad = kPadding * mScale;
    const float textY = (r.min.y + r.max.y - mFont->lineHeight()) * 0.5f;
    // A text longer than the field scrolls so that the caret stays in view (a long path typed at its end).
    const float caretX = mFont->measure(std::string_view(text).substr(0, caret));
    const float caretWidth = std::max(1.0f, mScale);
    const float scroll = std::max(0.0f, caretX + caretWidth - (field.max.x - field.min.x - 2.0f * pad));
    mDraw.pushClip(field);
    mDraw.text({field.min.x + pad - scroll, textY}, text, mStyle.text);
    if (isFocused(id)) {
        const float x = field.min.x + pad - scroll + caretX;
        mDraw.rect({{x, textY}, {x + caretWidth, textY + mFont->lineHeight()}}, mStyle.text);
    }
    mDraw.popClip();
    mDraw.textClipped({field.max.x + pad * 2.0f, textY}, visibleText(label), mStyle.text, r.max.x);
    return text != old;
}

bool Context::collapsingHeader(std::string_view label, bool defaultOpen) {
    const Rect r = row(rowHeight());
    const Id id = idOf(label);
    const Interaction in = interact(id, r, label);
    auto [it, inserted] = mOpen.try_emplace(id, defaultOpen);
    bool& open = it->second;
    if (in.clicked || in.activated) open = !open;
    drawFrame(r, id, in);
    // A small triangle: pointing right when closed, down when open.
    const float s = rowHeight() * 0.3f, pad = kPadding * mScale;
    const glm::vec2 c{r.min.x + pad + s, (r.min.y + r.max.y) * 0.5f};
    if (open)
        mDraw.quadrilateral({c.x - s, c.y - s * 0.5f}, {c.x + s, c.y - s * 0.5f}, {c.x, c.y + s * 0.6f},
                            {c.x, c.y + s * 0.6f}, mStyle.text);
    else
        mDraw.quadrilateral({c.x - s * 0.5f, c.y - s}, {c.x + s * 0.6f, c.y}, {c.x - s * 0.5f, c.y + s},
                            {c.x - s * 0.5f, c.y + s}, mStyle.text);
    mDraw.textClipped({c.x + s * 2.0f, (r.min.y + r.max.y - mFont->lineHeight()) * 0.5f}, visibleText(label),
                      mStyle.text, r.max.x - pad);
    return open;
}

bool Context::tabs(std::string_view label, int& selected, const std::vector<std::string>& names) {
    const Rect r = row(rowHeight());
    if (names.empty()) return false;
    const float w = (r.max.x - r.min.x) / float(names.size());
    bool changed = false;
    pushId(label);
    for (std::size_t i = 0; i < names.size(); ++i) {
        const Rect tab{{r.min.x + w * float(i), r.min.y}, {r.min.x + w * float(i + 1) - 1.0f, r.max.y}};
        const Id id = idOf(names[i]);
        const Interaction in = interact(id, tab, std::string(label) + "/" + names[i]);
        if (int(i) == selected) mDraw.rect(tab, mStyle.frameActive);
        else drawFrame(tab, id, in);
        if (isFocused(id) && int(i) == selected) drawFocusRing(tab);
        const float tw = mFont->measure(names[i]);
        mDraw.textClipped({std::max(tab.min.x + 2.0f, (tab.min.x + tab.max.x - tw) * 0.5f),
                           (r.min.y + r.max.y - mFont->lineHeight()) * 0.5f},
                          names[i], mStyle.text, tab.max.x - 2.0f);
        if ((in.clicked || in.activated) && int(i) != selected) {
            selected = int(i);
            changed = true;
        }
    }
    popId();
    mRects[std::string(label)] = r;
    mLastRect = r;
    return changed;
}

bool Context::splitter(std::string_view label, const Rect& area, bool verticalDivider, float& fraction) {
    const Id id = idOf(label);
    const float thick = 5.0f * mScale;
    const float old = fraction;
    fraction = std::clamp(fraction, 0.05f, 0.95f);
    Rect bar;
    if (verticalDivider) {
        const float x = area.min.x + fraction * (area.max.x - area.min.x);
        bar = {{x - thick * 0.5f, area.min.y}, {x + thick * 0.5f, area.max.y}};
    } else {
        const float y = area.min.y + fraction * (area.max.y - area.min.y);
        bar = {{area.min.x, y - thick * 0.5f}, {area.max.x, y + thick * 0.5f}};
    }
    const Interaction in = interact(id, bar, label, false);
    if (in.held || in.pressed) {
        const float f = verticalDivider ? (mInput.mouse.x - area.min.x) / std::max(1.0f, area.max.x - area.min.x)
                                        : (mInput.mouse.y - area.min.y) / std::max(1.0f, area.max.y - area.min.y);
        fraction = std::clamp(f, 0.05f, 0.95f);
    }
    mDraw.rect(bar, mActive == id ? mStyle.accent : in.hovered ? mStyle.frameHot : mStyle.frame);
    return fraction != old;
}

void Context::tooltip(std::string_view text) {
    if (mLastId == 0 || mHot != mLastId) {
        if (mHoverId == mLastId) mHoverId = 0;
        return;
    }
    if (mHoverId != mLastId) {
        mHoverId = mLastId;
        mHoverSince = mTime;
    }
    if (mTime - mHoverSince < kTooltipDelay) return;
    const float pad = kPadding * mScale;
    const glm::vec2 size{mFont->measure(text) + 2.0f * pad, mFont->lineHeight() + 2.0f * pad};
    glm::vec2 at = mInput.mouse + glm::vec2(12.0f, 16.0f) * mScale;
    at = glm::min(at, mDisplay - size);
    mOverlay.rect({at, at + size}, {0.05f, 0.05f, 0.06f, 0.95f});
    mOverlay.text(at + pad, text, mStyle.text);
}

void Context::tooltipNow(const std::vector<std::string>& lines) {
    if (lines.empty()) return;
    const float pad = kPadding * mScale, line = mFont->lineHeight();
    float width = 0.0f;
    for (const std::string& l : lines) width = std::max(width, mFont->measure(l));
    const glm::vec2 size{width + 2.0f * pad, float(lines.size()) * line + 2.0f * pad};
    glm::vec2 at = mInput.mouse + glm::vec2(12.0f, 16.0f) * mScale;
    at = glm::max(glm::min(at, mDisplay - size), glm::vec2(0.0f));
    mOverlay.rect({at, at + size}, {0.05f, 0.05f, 0.06f, 0.95f});
    for (std::size_t i = 0; i < lines.size(); ++i) mOverlay.text(at + pad + glm::vec2(0.0f, float(i) * line), lines[i], mStyle.text);
}

}  // namespace viz::ui
