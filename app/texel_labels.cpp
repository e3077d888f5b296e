#include "texel_labels.h"

#include <algorithm>
#include <cmath>

#include "core/text.h"

namespace airlight {

glm::ivec2 texelUnder(glm::ivec2 paneSize, const viz::ui::Rect& image, const viz::ui::ImageViewTransform& view,
                      glm::vec2 p) {
    const glm::dvec2 uv = view.paneToUv(glm::dvec2((p - image.min) / image.size()));
    return glm::clamp(glm::ivec2(glm::floor(uv * glm::dvec2(paneSize))), glm::ivec2(0), paneSize - 1);
}

std::optional<TexelBlock> labelledTexels(glm::ivec2 paneSize, const viz::ui::Rect& image,
                                         const viz::ui::ImageViewTransform& view, float lineHeight) {
    if (paneSize.x < 1 || paneSize.y < 1) return std::nullopt;
    const float cell = float(view.texelPixels(image.size().x, paneSize.x));
    if (cell < 4.2f * lineHeight) return std::nullopt;
    TexelBlock b{texelUnder(paneSize, image, view, image.min), texelUnder(paneSize, image, view, image.max - 1.0f)};
    if (b.count().x * b.count().y > 4096) return std::nullopt;
    return b;
}

std::vector<TexelLabel> texelLabels(const TexelBlock& block, glm::ivec2 paneSize, const viz::ui::Rect& image,
                                    const viz::ui::ImageViewTransform& view, int channels,
                                    const std::function<glm::vec4(int, int)>& value,
                                    const viz::ui::FontAtlas& font, float scale) {
    std::vector<TexelLabel> labels;
    const float line = font.lineHeight();
    const float cell = float(view.texelPixels(image.size().x, std::max(1, paneSize.x)));
    channels = std::clamp(channels, 1, 3);
    const bool allChannels = cell >= float(channels) * line + 4.0f * scale;
    for (int ty = block.lo.y; ty <= block.hi.y; ++ty)
        for (int tx = block.lo.x; tx <= block.hi.x; ++tx) {
            const glm::vec2 corner =
                image.min + glm::vec2(view.uvToPane(glm::dvec2(tx, ty) / glm::dvec2(paneSize))) * image.size();
            // The part of the texel inside the view holds the text.
            const glm::vec2 shownMin = glm::max(corner, image.min), shownMax = glm::min(corner + cell, image.max);
            if (shownMax.x - shownMin.x < 3.0f * line || shownMax.y - shownMin.y < line + 4.0f * scale) continue;
            const glm::vec4 v = value(tx, ty);
            for (int c = 0; c < (allChannels ? channels : 1); ++c) {
                const glm::vec2 at = shownMin + glm::vec2(3.0f * scale, 2.0f * scale + float(c) * line);
                if (at.y + line > shownMax.y) break;
                labels.push_back({at, viz::format("%.3g", v[c]), shownMax.x - 2.0f});
            }
        }
    return labels;
}

}  // namespace airlight
