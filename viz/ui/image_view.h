// Pan and zoom of an image inside a pane, down to single texels. Pane coordinates run (0,0) top-left to
// (1,1) bottom-right of the pane; image uv the same over the image (row 0 at the top). zoom = 1 shows
// the whole image (the pane keeps the image's aspect); zoom = k shows 1/k of it across.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace viz::ui {

struct ImageViewTransform {
    static constexpr double kMaxZoom = 4096.0;

    glm::dvec2 center{0.5};  // image uv at the pane's centre
    double zoom = 1.0;

    glm::dvec2 paneToUv(glm::dvec2 pane) const { return center + (pane - 0.5) / zoom; }
    glm::dvec2 uvToPane(glm::dvec2 uv) const { return (uv - center) * zoom + 0.5; }

    // Multiplies the zoom by `factor` (within [1, kMaxZoom]) keeping the image point under `pane` fixed.
    void zoomAt(glm::dvec2 pane, double factor) {
        const glm::dvec2 uv = paneToUv(pane);
        zoom = std::clamp(zoom * factor, 1.0, kMaxZoom);
        center = uv - (pane - 0.5) / zoom;
        clampCenter();
    }
    // Moves the view by a pane-coordinate delta (dragging the image by the mouse moves it with it).
    void panBy(glm::dvec2 paneDelta) {
        center -= paneDelta / zoom;
        clampCenter();
    }
    void fit() {
        center = glm::dvec2(0.5);
        zoom = 1.0;
    }
    // The view never leaves the image: the visible window [center -+ 0.5 / zoom] stays inside [0, 1].
    void clampCenter() {
        const double half = 0.5 / zoom;
        center = glm::clamp(center, glm::dvec2(half), glm::dvec2(1.0 - half));
    }
    // Screen pixels one texel covers, for an image `texels` wide shown `panePixels` wide.
    double texelPixels(double panePixels, double texels) const { return panePixels * zoom / texels; }
};

}  // namespace viz::ui
