// The window's view grid: a binary tree of splits whose leaves are views, each named by a small integer
// the app keys its per-view state with. Splitting a view adds a view beside it or below it; closing one
// gives its space to its sibling; swapping exchanges two views' places; maximising shows one view over
// the whole area until restored. Plain data and arithmetic (no GL, no window), so tests drive it directly.
//
// Text form (session file, screenshot sidecar): a leaf is its view number; a split is
// "x(F,A,B)" (A left of B, A taking the fraction F of the width) or "y(F,A,B)" (A above B, F of the
// height). Example: "x(0.5,0,y(0.5,1,2))" = view 0 on the left, views 1 over 2 on the right.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ui/text_renderer.h"

namespace airlight {

enum class SplitAxis { X, Y };  // X: side by side (divided along x); Y: stacked (divided along y)

struct ViewCellRect {
    int view = -1;
    viz::ui::Rect rect;  // window pixels, the cell's whole area (title, image, readout)
};

// The gap between the two sides of one split, which the user drags to move the split.
struct ViewDivider {
    std::string path;      // the split: kid indices from the root ("" = the root, "10" = first kid of its second kid)
    SplitAxis axis = SplitAxis::X;
    float fraction = 0.5f;  // the split's
    viz::ui::Rect strip;   // the gap, window pixels
    // The split's area less half a gap at each end along the axis: the gap's centre is at `fraction`
    // of it (what a ui::Context::splitter over it draws and sets).
    viz::ui::Rect track;
};

class ViewLayout {
public:
    // One view, number `view`, over the whole area.
    explicit ViewLayout(int view = 0);

    // Puts `added` beside (X: to the right) or below (Y) `view`, which keeps the first half. False when
    // `view` is not in the layout or `added` already is.
    bool split(int view, SplitAxis axis, int added, float fraction = 0.5f);
    // Removes `view`; its sibling takes the space. The last view cannot be closed (false).
    bool close(int view);
    // Exchanges the places of two views (false unless both are in the layout and differ).
    bool swap(int a, int b);
    // Shows `view` alone over the whole area; a second call with the same view (or restore()) goes back.
    void toggleMaximise(int view);
    void restore() { mMaximised = -1; }
    int maximised() const { return mMaximised; }

    bool contains(int view) const;
    // The views in reading order (depth first: left before right, top before bottom).
    std::vector<int> views() const;
    int count() const { return int(views().size()); }
    // The view after (or before, step -1) `view` in reading order, cycling.
    int next(int view, int step = 1) const;

    // Cell rectangles inside `area`, in reading order, `gap` pixels apart. Only the maximised view when
    // one is.
    std::vector<ViewCellRect> arrange(const viz::ui::Rect& area, float gap) const;
    // The dividers of every split inside `area` (none while a view is maximised), outer splits first.
    std::vector<ViewDivider> dividers(const viz::ui::Rect& area, float gap) const;
    // Sets the fraction of the split at `path` (clamped so that each side keeps 5 %). False when there is
    // no split there.
    bool setFraction(const std::string& path, float fraction);

    // The view whose cell holds `p`, or -1.
    static int hit(const std::vector<ViewCellRect>& cells, glm::vec2 p);

    std::string toText() const;
    // Parses toText()'s form; throws std::runtime_error naming the problem (bad syntax, a fraction outside
    // (0, 1), a view number twice or negative).
    static ViewLayout fromText(const std::string& text);

private:
    struct Node {
        int view = -1;  // >= 0: a leaf
        SplitAxis axis = SplitAxis::X;
        float fraction = 0.5f;
        std::vector<Node> kids;  // two for a split, none for a leaf
    };
    static Node* find(Node& n, int view);
    static bool removeLeaf(Node& n, int view);
    static void collect(const Node& n, std::vector<int>& out);
    static void place(const Node& n, const viz::ui::Rect& r, float gap, std::vector<ViewCellRect>& out);
    // The two sides of split `n` over `r`.
    static std::pair<viz::ui::Rect, viz::ui::Rect> sides(const Node& n, const viz::ui::Rect& r, float gap);
    static void collectDividers(const Node& n, const viz::ui::Rect& r, float gap, const std::string& path,
                                std::vector<ViewDivider>& out);
    static void write(const Node& n, std::string& out);

    Node mRoot;
    int mMaximised = -1;
};

}  // namespace airlight
