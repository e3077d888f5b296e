#include "colour_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "plot/plot.h"

namespace airlight {
namespace {

std::string figure(double v) { return shortNumber(v, 3); }

// The plot module's ticks for [lo, hi] that lie inside it, placed along the bar by `at`; when fewer than
// two fall inside, the two ends themselves.
void addTicks(ColourBar& bar, bool logarithmic, const std::function<float(double)>& at) {
    const viz::plot::AxisTicks axis = viz::plot::axisTicks(bar.lo, bar.hi, logarithmic, 5);
    for (std::size_t i = 0; i < axis.values.size(); ++i) {
        const double v = axis.values[i];
        const float place = at(v);  // inside the bar: [0, 1] up to rounding
        if (!(place >= -1e-5f && place <= 1.0f + 1e-5f)) continue;
        // A mapping that clamps (the diverging map's signedUnit) puts values beyond the ends at the ends.
        const double slack = 1e-6 * (bar.hi - bar.lo);
        if (v < bar.lo - slack || v > bar.hi + slack) continue;
        bar.ticks.push_back(v);
        bar.tickLabels.push_back(axis.labels[i]);
    }
    if (bar.ticks.size() < 2) {
        bar.ticks = {bar.lo, bar.hi};
        bar.tickLabels = {figure(bar.lo), figure(bar.hi)};
    }
    for (double v : bar.ticks) bar.tickAt.push_back(std::clamp(at(v), 0.0f, 1.0f));
}

// A ramp from lo to hi, linear or log10-spaced, with its ticks.
void ramp(ColourBar& bar, double lo, double hi, bool logarithmic) {
    bar.kind = ColourBar::Kind::Ramp;
    bar.logarithmic = logarithmic;
    if (logarithmic) {
        const ValueRange r = logSafeRange(float(lo), float(hi));
        lo = r.lo, hi = r.hi;
    }
    if (!(hi > lo)) hi = lo + (lo == 0.0 ? 1.0 : std::abs(lo) * 1e-3);
    bar.lo = lo, bar.hi = hi;
    const double a = logarithmic ? std::log10(lo) : lo, b = logarithmic ? std::log10(hi) : hi;
    for (int i = 0; i < kRampTexels; ++i) {
        const double t = (double(i) + 0.5) / double(kRampTexels), x = a + t * (b - a);
        bar.values.push_back(float(logarithmic ? std::pow(10.0, x) : x));
    }
    addTicks(bar, logarithmic, [&](double v) {
        return float(((logarithmic ? std::log10(v) : v) - a) / (b - a));
    });
}

// The diverging map over [-top, top]: its ramp inverts signedUnit (linear, or the symmetric log over four
// decades), and its ticks sit where signedUnit puts them.
void divergingRamp(ColourBar& bar, const DisplayMapping& m) {
    bar.kind = ColourBar::Kind::Ramp;
    bar.logarithmic = m.logScale;
    const double top = std::max({std::abs(double(m.lo)), std::abs(double(m.hi)), 1e-30});
    bar.lo = -top, bar.hi = top;
    for (int i = 0; i < kRampTexels; ++i) {
        const double s = 2.0 * (double(i) + 0.5) / double(kRampTexels) - 1.0;
        const double v = m.logScale ? std::copysign(top * (std::pow(1.0 + 1e4, std::abs(s)) - 1.0) / 1e4, s) : s * top;
        bar.values.push_back(float(v));
    }
    const auto at = [&](double v) { return 0.5f * (signedUnit(float(v), m.lo, m.hi, m.logScale) + 1.0f); };
    if (!m.logScale) {
        addTicks(bar, false, at);
        return;
    }
    for (double v : {-top, -top * 1e-2, 0.0, top * 1e-2, top}) {
        bar.ticks.push_back(v);
        bar.tickLabels.push_back(figure(v));
        bar.tickAt.push_back(at(v));
    }
}

void classes(ColourBar& bar, const std::vector<float>& values, const std::vector<std::string>& labels) {
    bar.kind = ColourBar::Kind::Classes;
    bar.values = values;
    bar.classLabels = labels;
    bar.lo = values.empty() ? 0.0 : values.front();
    bar.hi = values.empty() ? 0.0 : values.back();
}

}  // namespace

std::string shortNumber(double v, int digits) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v + 0.0);  // + 0.0: -0 reads "0", not "-0"
    return buf;
}

ColourBar colourBarFor(const PaneImage& pane, const DisplayMapping& m, const SpecialCounts& counts) {
    ColourBar bar;
    if (!pane.plots.empty() || pane.texture == 0 || pane.size.x <= 0 || pane.size.y <= 0) return bar;
    const viz::ChannelInfo* declared = declaredChannel(pane, m.channel);
    bar.units = declared ? declared->units : pane.units;
    if (declared) bar.caption = declared->name;
    const bool mapped = m.mode != DisplayMode::HdrColour && m.mode != DisplayMode::RangeColour;
    if (pane.picture && !mapped) {
        bar.kind = ColourBar::Kind::Picture;
        bar.caption = "a picture drawn by the technique: the note above says what its colours mean";
    } else switch (m.mode) {
        case DisplayMode::HdrColour:
        case DisplayMode::RangeColour: {
            // Colour images: each channel on its own; the bar shows the greys, up to the value that the
            // exposure takes to white.
            const double white = std::exp2(-double(m.exposure));
            if (m.mode == DisplayMode::HdrColour) {
                ramp(bar, 0.0, white, false);
                bar.caption = "white = " + figure(white) + " (" + figure(m.exposure) + " EV)";
            } else {
                const double u = std::min(white, 1.0);
                double top = m.lo + u * (double(m.hi) - m.lo);
                if (m.logScale) {
                    const ValueRange r = logSafeRange(m.lo, m.hi);
                    top = std::pow(10.0, std::log10(r.lo) + u * (std::log10(r.hi) - std::log10(r.lo)));
                }
                ramp(bar, m.lo, top, m.logScale);
                bar.caption = (declared ? declared->name + ", " : std::string("each colour channel, ")) +
                              (m.exposure != 0.0f ? "exposure " + figure(m.exposure) + " EV" : std::string("as a colour"));
                if (m.exposure != 0.0f) bar.shortCaption = (m.exposure > 0.0f ? "+" : "") + figure(m.exposure) + " EV";
            }
            break;
        }
        case DisplayMode::Grey:
        case DisplayMode::FalseColour:
        case DisplayMode::Heat: ramp(bar, m.lo, m.hi, m.logScale); break;
        case DisplayMode::Signed:
            divergingRamp(bar, m);
            if (bar.caption.empty()) bar.caption = "blue below 0, white at 0, red above";
            break;
        case DisplayMode::Bits:
            classes(bar, {0, 1, 2, 3, 4, 5, 6, 7}, {"0", "1", "2", "3", "4", "5", "6", "7"});
            bar.caption = "each integer value its own colour, 0 black";
            break;
        case DisplayMode::Categorical: {
            const double first = std::floor(std::clamp(double(m.lo), -1e6, 1e6));
            const int n = int(std::clamp(std::floor(double(m.hi)) - first + 1.0, 1.0, 10.0));
            std::vector<float> values;
            std::vector<std::string> labels;
            for (int k = 0; k < n; ++k) values.push_back(float(first + k)), labels.push_back(figure(first + k));
            classes(bar, values, labels);
            bar.caption = "floor(value): 10 colours, repeating";
            break;
        }
        case DisplayMode::Mask: {
            const double mid = 0.5 * (double(m.lo) + m.hi);
            classes(bar, {m.lo, m.hi}, {"<= " + figure(mid), "> " + figure(mid)});
            bar.caption = "white above the middle of the range";
            break;
        }
    }
    const auto add = [&](std::string label, float value, std::size_t pixels, bool sentinel) {
        bar.legend.push_back({std::move(label), value, pixels, sentinel});
    };
    // Sentinels first (they explain part of the picture), then the overlays (NaN, Inf, negative).
    for (std::size_t k = 0; k < pane.sentinels.size(); ++k) {
        const viz::Sentinel& s = pane.sentinels[k];
        add(figure(s.value) + ": " + s.meaning, s.value, k < counts.sentinel.size() ? counts.sentinel[k] : 0, true);
    }
    add("NaN", std::numeric_limits<float>::quiet_NaN(), counts.nan, false);
    add("Inf", std::numeric_limits<float>::infinity(), counts.inf, false);
    if (m.markNegative) {
        // Any negative value that is not a sentinel draws the negative overlay.
        float negative = -0.5f;
        for (const viz::Sentinel& s : pane.sentinels)
            if (s.value == negative) negative *= 0.5f;
        add("negative", negative, counts.negative, false);
    }
    return bar;
}

std::optional<MaskPixels> countMaskPixels(const DisplayMapping& m, const viz::Image& values, int meaningful,
                                          const std::vector<viz::Sentinel>& sentinels) {
    if (m.mode != DisplayMode::Mask || values.empty()) return std::nullopt;
    const int channels = std::clamp(meaningful, 1, values.channels);
    MaskPixels out;
    for (int y = 0; y < values.height; ++y)
        for (int x = 0; x < values.width; ++x) {
            bool special = false;
            for (int c = 0; c < channels; ++c) special = special || !std::isfinite(values.at(x, y, c));
            const float v = shownScalar(&values.pixels[values.index(x, y)], channels, m.channel);
            if (special || std::isnan(v)) continue;  // NaN: the texel lacks the chosen channel
            if (std::any_of(sentinels.begin(), sentinels.end(), [&](const viz::Sentinel& s) { return s.value == v; }))
                continue;
            ++out.counted;
            out.white += mapToUnit(v, m.lo, m.hi, m.logScale) > 0.5f ? 1 : 0;
        }
    return out;
}

void describeMaskPixels(ColourBar& bar, const MaskPixels& pixels) {
    if (bar.kind != ColourBar::Kind::Classes) return;
    bar.caption += ": " + std::to_string(pixels.white) + " of " + std::to_string(pixels.counted) + " pixels";
}

}  // namespace airlight
