#include "ray_inspector.h"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "core/text.h"
#include "plot/plot.h"
#include "report/first_hits.h"
#include "ui/theme.h"

namespace airlight {

using viz::format;
using viz::ui::Rect;

namespace {

// The technique's rasterised distance to the pixel's first surface (its `.distance` view), if it has one.
std::optional<float> drawnDistance(const PixelInspection* seen) {
    if (!seen) return std::nullopt;
    for (const PixelReading& r : seen->readings)
        if (r.channels >= 1 && r.id.ends_with(".distance") && r.id != "reference.distance") return r.value.x;
    return std::nullopt;
}

}  // namespace

void RayInspector::inspect(const viz::scene::Scene& scene, glm::ivec2 frame, glm::ivec2 pixel,
                           const std::string& technique, const viz::Image* airlight) {
    clear();
    mProbe = viz::reference::probePixel(scene, frame.x, frame.y, pixel.x, pixel.y);
    mTechnique = technique;
    if (airlight && airlight->width == frame.x && airlight->height == frame.y)
        mValue = glm::dvec3(airlight->at(pixel.x, pixel.y, 0), airlight->at(pixel.x, pixel.y, 1),
                            airlight->at(pixel.x, pixel.y, 2));
}

void RayInspector::clear() {
    mProbe.reset();
    mTechnique.clear();
    mValue.reset();
    mReadings.reset();
}

const PixelInspection& RayInspector::readings(const viz::Technique& technique, const viz::FrameOutput& out,
                                              glm::ivec2 frame) {
    if (!mReadings) mReadings = inspectRun(technique, out, frame, pixel());
    return *mReadings;
}

void RayInspector::draw(viz::ui::DrawList& dl, const Rect& area, float line, float scale,
                        const PixelInspection* seen) const {
    using namespace viz::ui::theme;
    const auto& p = *mProbe;
    const double ref = p.airlight.x + p.airlight.y + p.airlight.z;
    const std::string head = "ray inspector (I): pixel (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                             ")  d = " + format("%.3g", p.d) + "  reference L_air = " + format("%.4g", p.airlight.x) +
                             format(" %.4g", p.airlight.y) + format(" %.4g", p.airlight.z);
    std::string second = mTechnique + ": ";
    if (mValue) {
        const double v = mValue->x + mValue->y + mValue->z;
        second += format("%.4g", mValue->x) + format(" %.4g", mValue->y) + format(" %.4g", mValue->z) +
                  (ref > 0.0 ? "   relative error " + format("%+.2f%%", 100.0 * (v - ref) / ref) : "");
    } else {
        second += "(no value at this resolution yet)";
    }
    dl.textClipped(area.min, head, kText, area.max.x);
    dl.textClipped({area.min.x, area.min.y + line}, second, kDim, area.max.x);
    // A silhouette pixel (report/first_hits.h): the rasteriser and the traced ray see different surfaces.
    float lines = 2.0f;
    const std::optional<float> drawn = drawnDistance(seen);
    if (drawn && !viz::report::firstHitsAgree(float(p.d), *drawn)) {
        dl.textClipped({area.min.x, area.min.y + 2.0f * line},
                       "silhouette pixel: rasterised d = " + format("%.4g", *drawn) + ", traced " +
                           format("%.4g", p.d) + ": no raster technique can match",
                       kError, area.max.x);
        lines = 3.0f;
    }
    viz::plot::PlotSpec spec;
    spec.xLabel = "t along the ray";
    spec.yLabel = "integrand (sum of RGB), V included";
    viz::plot::Series curve{"integrand", viz::plot::categoricalColour(0), {}, true, false};
    for (std::size_t i = 0; i < p.t.size(); ++i) {
        const glm::dvec3& v = p.integrand[i];
        curve.points.push_back({p.t[i], v.x + v.y + v.z});
    }
    spec.series.push_back(std::move(curve));
    // The technique's own samples along the ray (slices: one point per plane), on the same axes.
    if (seen)
        for (const viz::plot::Series& s : seen->series) spec.series.push_back(s);
    for (std::size_t k = 0; k < p.lights.size(); ++k) {
        viz::plot::Band band{"lit: " + p.lights[k].name, viz::plot::categoricalColour(int(k) + 1), {}};
        for (const auto& iv : p.lights[k].lit) band.spans.push_back({iv.a, iv.b});
        spec.bands.push_back(std::move(band));
    }
    Rect plotArea{{area.min.x, area.min.y + lines * line + 4.0f * scale}, area.max};
    // The technique's own view of the ray beside the plot: its per-pixel intermediates at this pixel
    // and the per-ray views that follow the picked pixel.
    if (seen && plotArea.size().x > 500.0f * scale) {
        const Rect side{{plotArea.max.x - 0.42f * plotArea.size().x, plotArea.min.y}, plotArea.max};
        plotArea.max.x = side.min.x - kPad * scale;
        float y = side.min.y;
        std::string title = mTechnique + " at this pixel";
        if (!seen->rayViews.empty()) {
            title += " (its ray in views:";
            for (const std::string& id : seen->rayViews) title += " " + id;
            title += ")";
        }
        dl.textClipped({side.min.x, y}, title + ":", kAccent, side.max.x);
        y += line;
        for (const PixelReading& r : seen->readings) {
            if (y + line > side.max.y) break;
            std::string text = r.label + ":";
            for (int c = 0; c < std::min(r.channels, 4); ++c) text += format(" %.4g", r.value[c]);
            if (!r.units.empty()) text += " " + r.units;
            dl.textClipped({side.min.x, y}, text, kText, side.max.x);
            y += line;
        }
    }
    if (plotArea.size().y > 4.0f * line) viz::plot::drawPlot(dl, plotArea, spec);
}

void RayInspector::mark(viz::ui::DrawList& dl, const Rect& image, const viz::ui::ImageViewTransform& transform,
                        glm::ivec2 frame, float scale) const {
    if (!mProbe || frame.x < 1 || frame.y < 1) return;
    const glm::dvec2 uv = (glm::dvec2(mProbe->x, mProbe->y) + 0.5) / glm::dvec2(frame);
    const glm::vec2 c = image.min + glm::vec2(transform.uvToPane(uv)) * image.size();
    if (!image.contains(c)) return;
    const float r = 6.0f * scale;
    const glm::vec4 magenta{1.0f, 0.2f, 0.8f, 1.0f};
    dl.line({c.x - r, c.y}, {c.x + r, c.y}, 2.0f * scale, magenta);
    dl.line({c.x, c.y - r}, {c.x, c.y + r}, 2.0f * scale, magenta);
}

nlohmann::json RayInspector::sidecar(const PixelInspection* seen) const {
    const auto rgb = [](glm::dvec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); };
    nlohmann::json lights = nlohmann::json::array();
    for (const auto& l : mProbe->lights) {
        nlohmann::json spans = nlohmann::json::array();
        for (const auto& iv : l.lit) spans.push_back({iv.a, iv.b});
        lights.push_back({{"name", l.name}, {"lit", spans}, {"airlight", rgb(l.airlight)}});
    }
    nlohmann::json out = {{"pixel", {mProbe->x, mProbe->y}},
                          {"d", mProbe->d},
                          {"reference", rgb(mProbe->airlight)},
                          {"technique", mTechnique},
                          {"technique_value", mValue ? rgb(*mValue) : nlohmann::json(nullptr)},
                          {"lights", lights}};
    if (seen) {
        nlohmann::json readings = nlohmann::json::object();
        for (const PixelReading& r : seen->readings) {
            std::vector<double> values;
            for (int c = 0; c < r.channels; ++c) values.push_back(r.value[c]);
            readings[r.id] = values;
        }
        out["readings"] = readings;
        out["ray_views"] = seen->rayViews;
        nlohmann::json series = nlohmann::json::object();
        for (const viz::plot::Series& s : seen->series) {
            nlohmann::json points = nlohmann::json::array();
            for (const glm::dvec2& q : s.points) points.push_back({q.x, q.y});
            series[s.name] = points;
        }
        out["ray_series"] = series;
        if (const std::optional<float> drawn = drawnDistance(seen))
            out["first_hit"] = {{"drawn", *drawn},
                                {"traced", mProbe->d},
                                {"agree", viz::report::firstHitsAgree(float(mProbe->d), *drawn)}};
    }
    return out;
}

}  // namespace airlight
