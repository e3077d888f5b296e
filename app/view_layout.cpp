#include "view_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <set>
#include <stdexcept>

namespace airlight {

ViewLayout::ViewLayout(int view) { mRoot.view = view; }

ViewLayout::Node* ViewLayout::find(Node& n, int view) {
    if (n.kids.empty()) return n.view == view ? &n : nullptr;
    for (Node& k : n.kids)
        if (Node* f = find(k, view)) return f;
    return nullptr;
}

bool ViewLayout::contains(int view) const { return find(const_cast<Node&>(mRoot), view) != nullptr; }

bool ViewLayout::split(int view, SplitAxis axis, int added, float fraction) {
    if (added < 0 || contains(added)) return false;
    Node* leaf = find(mRoot, view);
    if (!leaf) return false;
    Node first;
    first.view = view;
    Node second;
    second.view = added;
    leaf->view = -1;
    leaf->axis = axis;
    leaf->fraction = std::clamp(fraction, 0.05f, 0.95f);
    leaf->kids = {first, second};
    return true;
}

// Replaces the split holding leaf `view` by the leaf's sibling.
bool ViewLayout::removeLeaf(Node& n, int view) {
    for (std::size_t i = 0; i < n.kids.size(); ++i) {
        Node& k = n.kids[i];
        if (k.kids.empty() && k.view == view) {
            Node sibling = n.kids[1 - i];
            n = std::move(sibling);
            return true;
        }
        if (removeLeaf(k, view)) return true;
    }
    return false;
}

bool ViewLayout::close(int view) {
    if (mRoot.kids.empty()) return false;  // the last view stays
    if (!removeLeaf(mRoot, view)) return false;
    if (mMaximised == view) mMaximised = -1;
    return true;
}

bool ViewLayout::swap(int a, int b) {
    if (a == b) return false;
    Node* na = find(mRoot, a);
    Node* nb = find(mRoot, b);
    if (!na || !nb) return false;
    std::swap(na->view, nb->view);
    return true;
}

void ViewLayout::toggleMaximise(int view) {
    if (mMaximised == view || !contains(view)) mMaximised = -1;
    else mMaximised = view;
}

void ViewLayout::collect(const Node& n, std::vector<int>& out) {
    if (n.kids.empty()) {
        out.push_back(n.view);
        return;
    }
    for (const Node& k : n.kids) collect(k, out);
}

std::vector<int> ViewLayout::views() const {
    std::vector<int> out;
    collect(mRoot, out);
    return out;
}

int ViewLayout::next(int view, int step) const {
    const std::vector<int> all = views();
    const auto it = std::find(all.begin(), all.end(), view);
    if (it == all.end()) return all.front();
    const int n = int(all.size());
    const int i = int(it - all.begin());
    return all[std::size_t(((i + step) % n + n) % n)];
}

std::pair<viz::ui::Rect, viz::ui::Rect> ViewLayout::sides(const Node& n, const viz::ui::Rect& r, float gap) {
    viz::ui::Rect a = r, b = r;
    if (n.axis == SplitAxis::X) {
        const float w = std::max(0.0f, r.size().x - gap);
        a.max.x = r.min.x + w * n.fraction;
        b.min.x = a.max.x + gap;
    } else {
        const float h = std::max(0.0f, r.size().y - gap);
        a.max.y = r.min.y + h * n.fraction;
        b.min.y = a.max.y + gap;
    }
    return {a, b};
}

void ViewLayout::place(const Node& n, const viz::ui::Rect& r, float gap, std::vector<ViewCellRect>& out) {
    if (n.kids.empty()) {
        out.push_back({n.view, r});
        return;
    }
    const auto [a, b] = sides(n, r, gap);
    place(n.kids[0], a, gap, out);
    place(n.kids[1], b, gap, out);
}

void ViewLayout::collectDividers(const Node& n, const viz::ui::Rect& r, float gap, const std::string& path,
                                 std::vector<ViewDivider>& out) {
    if (n.kids.empty()) return;
    const auto [a, b] = sides(n, r, gap);
    viz::ui::Rect strip = r, track = r;
    if (n.axis == SplitAxis::X) {
        strip.min.x = a.max.x, strip.max.x = b.min.x;
        track.min.x += 0.5f * gap, track.max.x -= 0.5f * gap;
    } else {
        strip.min.y = a.max.y, strip.max.y = b.min.y;
        track.min.y += 0.5f * gap, track.max.y -= 0.5f * gap;
    }
    out.push_back({path, n.axis, n.fraction, strip, track});
    collectDividers(n.kids[0], a, gap, path + "0", out);
    collectDividers(n.kids[1], b, gap, path + "1", out);
}

std::vector<ViewDivider> ViewLayout::dividers(const viz::ui::Rect& area, float gap) const {
    std::vector<ViewDivider> out;
    if (mMaximised >= 0 && contains(mMaximised)) return out;
    collectDividers(mRoot, area, gap, "", out);
    return out;
}

bool ViewLayout::setFraction(const std::string& path, float fraction) {
    Node* n = &mRoot;
    for (const char c : path) {
        if (n->kids.size() != 2 || (c != '0' && c != '1')) return false;
        n = &n->kids[std::size_t(c - '0')];
    }
    if (n->kids.size() != 2 || !std::isfinite(fraction)) return false;
    n->fraction = std::clamp(fraction, 0.05f, 0.95f);
    return true;
}

std::vector<ViewCellRect> ViewLayout::arrange(const viz::ui::Rect& area, float gap) const {
    std::vector<ViewCellRect> out;
    if (mMaximised >= 0 && contains(mMaximised)) {
        out.push_back({mMaximised, area});
        return out;
    }
    place(mRoot, area, gap, out);
    return out;
}

int ViewLayout::hit(const std::vector<ViewCellRect>& cells, glm::vec2 p) {
    for (const ViewCellRect& c : cells)
        if (c.rect.contains(p)) return c.view;
    return -1;
}

// ---- text form ----

void ViewLayout::write(const Node& n, std::string& out) {
    if (n.kids.empty()) {
        out += std::to_string(n.view);
        return;
    }
    char fraction[32];
    std::snprintf(fraction, sizeof fraction, "%.4g", double(n.fraction));
    out += n.axis == SplitAxis::X ? "x(" : "y(";
    out += fraction;
    out += ',';
    write(n.kids[0], out);
    out += ',';
    write(n.kids[1], out);
    out += ')';
}

std::string ViewLayout::toText() const {
    std::string out;
    write(mRoot, out);
    return out;
}

namespace {

// Recursive descent over "x(F,A,B)" / "y(F,A,B)" / "N".
struct Parser {
    const std::string& s;
    std::size_t i = 0;
    std::set<int> seen;

    [[noreturn]] void fail(const std::string& why) const {
        throw std::runtime_error("layout '" + s + "': " + why + " at character " + std::to_string(i + 1));
    }
    void expect(char c) {
        if (i >= s.size() || s[i] != c) fail(std::string("expected '") + c + "'");
        ++i;
    }
    double number() {
        const char* begin = s.c_str() + i;
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        if (end == begin) fail("expected a number");
        i += std::size_t(end - begin);
        return v;
    }
};

}  // namespace

ViewLayout ViewLayout::fromText(const std::string& text) {
    Parser p{text, 0, {}};
    // A lambda that calls itself through a reference, once per level: the depth is capped so that no
    // text (a session file is user input) can exhaust the stack.
    constexpr int kMaxDepth = 32;
    int depth = 0;
    const std::function<Node()> node = [&]() -> Node {
        Node n;
        if (p.i < text.size() && (text[p.i] == 'x' || text[p.i] == 'y')) {
            if (++depth > kMaxDepth) p.fail("layout nested deeper than " + std::to_string(kMaxDepth));
            n.axis = text[p.i] == 'x' ? SplitAxis::X : SplitAxis::Y;
            ++p.i;
            p.expect('(');
            const double f = p.number();
            if (!(f > 0.0 && f < 1.0)) p.fail("split fraction outside (0, 1)");
            n.fraction = float(f);
            p.expect(',');
            n.kids.push_back(node());
            p.expect(',');
            n.kids.push_back(node());
            p.expect(')');
            --depth;
            return n;
        }
        if (p.i >= text.size() || text[p.i] < '0' || text[p.i] > '9') p.fail("expected a view number or x( / y(");
        const double v = p.number();
        if (v != double(int(v)) || v < 0 || v > 1e6) p.fail("bad view number");
        n.view = int(v);
        if (!p.seen.insert(n.view).second) p.fail("view " + std::to_string(n.view) + " appears twice");
        return n;
    };
    ViewLayout layout;
    layout.mRoot = node();
    if (p.i != text.size()) p.fail("unexpected text after the layout");
    return layout;
}

}  // namespace airlight
