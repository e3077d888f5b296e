#include "view_markers.h"

#include <algorithm>
#include <set>
#include <string>

namespace airlight {

using viz::ui::DrawList;
using viz::ui::Rect;

namespace {

// Whether `r` overlaps none of the rectangles placed so far.
bool clearOf(const Rect& r, const std::vector<Rect>& placed) {
    return std::none_of(placed.begin(), placed.end(), [&](const Rect& p) {
        return r.min.x < p.max.x && p.min.x < r.max.x && r.min.y < p.max.y && p.min.y < r.max.y;
    });
}

}  // namespace

std::string otherLayersNote(const std::vector<viz::ViewMarker>& marks, int layer, int layers) {
    std::set<int> others;
    for (const viz::ViewMarker& m : marks)
        if (m.layer >= 0 && m.layer != layer) others.insert(m.layer);
    if (others.empty()) return {};
    std::string list;
    std::size_t i = 0;
    for (const int l : others) {
        if (i > 0) list += i + 1 == others.size() ? " and " : ", ";
        list += std::to_string(l + 1);
        ++i;
    }
    return std::string("marks on layer") + (others.size() > 1 ? "s " : " ") + list + " of " +
           std::to_string(std::max(layers, *others.rbegin() + 1)) + " (, / . to step)";
}

void drawCrosshair(DrawList& dl, glm::vec2 c, const Rect& clip, float scale) {
    if (!clip.contains(c)) return;
    const float r = 7.0f * scale, w = 1.5f * scale;
    for (int pass = 0; pass < 2; ++pass) {
        const float width = pass == 0 ? w + 2.0f * scale : w;
        const glm::vec4 colour = pass == 0 ? glm::vec4(0.0f, 0.0f, 0.0f, 0.8f) : glm::vec4(0.2f, 1.0f, 1.0f, 1.0f);
        dl.line({c.x - r, c.y}, {c.x - 2.0f * scale, c.y}, width, colour);
        dl.line({c.x + 2.0f * scale, c.y}, {c.x + r, c.y}, width, colour);
        dl.line({c.x, c.y - r}, {c.x, c.y - 2.0f * scale}, width, colour);
        dl.line({c.x, c.y + 2.0f * scale}, {c.x, c.y + r}, width, colour);
    }
}

std::vector<Rect> drawViewMarkers(DrawList& dl, const viz::ui::FontAtlas& font, float scale, const ViewState& v,
                                   const std::vector<viz::ViewMarker>& marks) {
    const auto toWindow = [&](glm::vec2 data) {
        const glm::dvec2 uv{data.x, v.pane.glRows ? 1.0 - double(data.y) : double(data.y)};
        return v.image.min + glm::vec2(v.transform.uvToPane(uv)) * v.image.size();
    };
    dl.pushClip(v.image);
    std::vector<Rect> placed;  // labels drawn so far
    glm::vec4 colour(0.0f);
    float width = 1.0f;
    const float line = font.lineHeight();
    const auto shown = [&](const viz::ViewMarker& m) { return m.layer < 0 || m.layer == v.pane.layer; };
    // Several labelled points (a ray's crossings lie close together): each gets a number beside it and
    // its label goes into a key at the image's bottom left, so that labels do not pile up; the lines'
    // labels go there too (first, in their colours), so that none lies over the numbers.
    const auto points = std::count_if(marks.begin(), marks.end(), [&](const viz::ViewMarker& m) {
        return shown(m) && m.from == m.to && !m.label.empty();
    });
    std::vector<std::pair<std::string, glm::vec4>> key, lineKey;
    int tags = 0;
    for (std::size_t i = 0; i < marks.size(); ++i) {
        if (!shown(marks[i])) continue;
        const glm::vec2 a = toWindow(marks[i].from), b = toWindow(marks[i].to);
        // The first mark thin cyan, the others yellow; an unlabelled one continues the previous (a
        // polyline).
        if (i == 0 || !marks[i].label.empty()) {
            colour = i == 0 ? glm::vec4(0.2f, 1.0f, 1.0f, 0.9f) : glm::vec4(1.0f, 0.85f, 0.2f, 1.0f);
            width = i == 0 ? 1.0f : 2.0f;
        }
        if (a == b) {
            drawCrosshair(dl, a, v.image, scale);
        } else {
            dl.line(a, b, 3.0f * scale, {0.0f, 0.0f, 0.0f, 0.6f});
            dl.line(a, b, width * scale, colour);
        }
        const glm::vec2 at{std::max(std::min(a.x, b.x), v.image.min.x) + 4.0f * scale,
                           std::min(a.y, b.y) - line - 2.0f * scale};
        if (marks[i].label.empty()) continue;  // a piece of a polyline labelled once
        if (points > 2 && a != b) {
            lineKey.push_back({marks[i].label, colour});
            continue;
        }
        if (a == b && points > 2) {
            // The number above right of its point, else below right, above left, below left: the first
            // place clear of the numbers and labels placed before it.
            const std::string tag = std::to_string(++tags);
            const glm::vec2 size{font.measure(tag) + 2.0f, line};
            const float gap = 5.0f * scale;
            const glm::vec2 candidates[] = {{a.x + gap, a.y - line - 1.0f}, {a.x + gap, a.y + 1.0f},
                                            {a.x - gap - size.x, a.y - line - 1.0f}, {a.x - gap - size.x, a.y + 1.0f}};
            glm::vec2 tagAt = candidates[0];
            for (const glm::vec2 c : candidates)
                if (clearOf({c - 1.0f, c + size}, placed)) {
                    tagAt = c;
                    break;
                }
            placed.push_back({tagAt - 1.0f, tagAt + size});
            dl.rect({tagAt - 1.0f, tagAt + size}, {0.0f, 0.0f, 0.0f, 0.6f});
            dl.textClipped(tagAt, tag, colour, v.image.max.x);
            key.push_back({tag + "  " + marks[i].label, glm::vec4(1.0f, 0.85f, 0.2f, 1.0f)});
            continue;
        }
        // A label that would run past the image's right edge moves left to end there; one that would
        // cover a label already placed moves down a line (marks close together, e.g. a ray's crossings).
        const float labelWidth = font.measure(marks[i].label);
        const float labelX = i == 0 ? at.x : std::max(a.x, b.x) + 4.0f * scale;
        glm::vec2 labelAt{std::max(v.image.min.x, std::min(labelX, v.image.max.x - labelWidth - 2.0f)),
                          std::clamp(i == 0 ? at.y : std::max(a.y, b.y) + 2.0f * scale, v.image.min.y,
                                     v.image.max.y - line)};
        for (int tries = 0; tries < 8 && !clearOf({labelAt, labelAt + glm::vec2(labelWidth, line)}, placed); ++tries)
            labelAt.y += line + 1.0f;
        placed.push_back({labelAt, labelAt + glm::vec2(labelWidth, line)});
        dl.rect({labelAt - 1.0f, labelAt + glm::vec2(labelWidth + 2.0f, line)}, {0.0f, 0.0f, 0.0f, 0.6f});
        dl.textClipped(labelAt, marks[i].label, colour, v.image.max.x);
    }
    key.insert(key.begin(), lineKey.begin(), lineKey.end());
    const std::string elsewhere = otherLayersNote(marks, v.pane.layer, v.pane.layers);
    if (!elsewhere.empty()) key.push_back({elsewhere, glm::vec4(0.2f, 1.0f, 1.0f, 0.9f)});
    if (!key.empty()) {
        float keyWidth = 0.0f;
        for (const auto& k : key) keyWidth = std::max(keyWidth, font.measure(k.first));
        const float pad = 3.0f * scale;
        const glm::vec2 origin{v.image.min.x + pad, v.image.max.y - pad - float(key.size()) * line};
        dl.rect({origin - pad, origin + glm::vec2(keyWidth + pad, float(key.size()) * line + pad)},
                {0.0f, 0.0f, 0.0f, 0.7f});
        for (std::size_t k = 0; k < key.size(); ++k)
            dl.textClipped(origin + glm::vec2(0.0f, float(k) * line), key[k].first, key[k].second, v.image.max.x);
    }
    dl.popClip();
    return placed;
}

}  // namespace airlight
