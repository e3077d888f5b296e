// One image shown in a window pane: a 2D float texture plus how to map it to the screen (exposure,
// range, colour map by the intermediate's kind), made from a technique's CPU image or GL texture.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "core/image.h"
#include "debug/technique.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "plot/plot.h"
#include "ui/image_view.h"
#include "ui/text_renderer.h"
#include "view_stats.h"

namespace airlight {

// Mirrors the modes of shaders/ui/image.frag.
enum class DisplayMode : int {
    HdrColour = 0, RangeColour = 1, Grey = 2, Signed = 3, FalseColour = 4, Bits = 5, Mask = 6, Categorical = 7, Heat = 8
};

DisplayMode displayModeFor(viz::ViewKind kind);

// What a pane shows: a 2D float texture plus how to map it, or the reason nothing can be shown.
struct PaneImage {
    std::string id, label, note, units;
    viz::ViewKind kind = viz::ViewKind::Colour;
    DisplayMode mode = DisplayMode::HdrColour;
    float rangeMin = 0.0f, rangeMax = 1.0f;
    GLuint texture = 0;   // borrowed (technique's) or `owned`
    viz::gl::Texture owned;
    bool flipY = false;   // true for textures rendered by GL (row 0 at the bottom)
    // The data's rows are a GL texture's (row 0 at the bottom), shown directly (flipY) or read back
    // (a layer of an array or cube, rows flipped by the readback): technique marks use these rows.
    bool glRows = false;
    int channels = 4;
    glm::ivec2 size{0};
    int layer = 0, layers = 1;
    std::string unavailable;  // non-empty: nothing to draw, and why
    std::vector<viz::PlotData> plots;  // drawn instead of the texture when not empty (the technique's plots)
    std::vector<viz::Sentinel> sentinels;       // values that mean "nothing here" (hatched, not counted)
    std::vector<viz::ChannelInfo> channelInfo;  // the quantities packed in r, g, b, a; empty: one quantity
    bool picture = false;                       // drawn by the technique: its note explains its colours
    bool rangeFromData = false;                 // Intermediate::rangeFromData
    bool rangeGrowsToData = false;              // Intermediate::rangeGrowsToData
};

// The channel a view starts on for a pane: the first declared quantity of a multi-quantity pane, else all.
Channel defaultChannel(const PaneImage& pane);
// The channel picker's entries for a pane (index = Channel): the declared quantities' names in place of
// R, G, B, A ("r: faces crossed"), and only the entries that show something.
std::vector<std::string> channelChoices(const PaneImage& pane);
// The declared quantity a channel shows, or nullptr (RGB, luminance, or an undeclared pane).
const viz::ChannelInfo* declaredChannel(const PaneImage& pane, Channel channel);

// A technique's plot as the plot module draws it (colours from the categorical palette).
viz::plot::PlotSpec plotSpecOf(const viz::PlotData& data);

// Where a view's value range comes from: the technique's suggestion (or the window's exposure for HDR
// colour), the finite min/max, the 0.1 and 99.9 percentiles of the finite values, or two numbers.
enum class RangeMode : int { Suggested = 0, MinMax = 1, Percentiles = 2, Manual = 3 };
const std::vector<std::string>& rangeModeNames();
// A colour map chosen over the one the intermediate's kind suggests.
enum class ColourMap : int { Auto = 0, Grey = 1, Sequential = 2, Ramp = 3, Diverging = 4, Bits = 5, Categorical = 6 };
const std::vector<std::string>& colourMapNames();

// One view's display controls (the strip under its title); each view keeps its own.
struct DisplaySettings {
    Channel channel = Channel::Rgb;
    RangeMode range = RangeMode::Suggested;
    float manualMin = 0.0f, manualMax = 1.0f;
    bool logScale = false;
    ColourMap colourMap = ColourMap::Auto;
    // Negative values in green (NaN and Inf are always marked): -1 = auto, on for radiance images (where
    // a negative value is a bug) and off for data (where -1 may mean "outside the cone"); 0 off; 1 on.
    int markNegative = -1;
    DifferenceMode difference = DifferenceMode::Off;
    std::string against = "reference";  // the technique the difference is taken to
    bool stripOpen = false;
};

// What the shader is given for one draw: the settings resolved against the pane and its statistics.
struct DisplayMapping {
    DisplayMode mode = DisplayMode::HdrColour;
    float lo = 0.0f, hi = 1.0f;  // linear range (the shader takes log10 of a log-safe range itself)
    float exposure = 0.0f;       // stops, colour modes only
    Channel channel = Channel::Rgb;
    bool logScale = false, markNegative = false;
};

// `autoRange`: the view's finite min/max or percentiles (per the settings), when known. A declared
// channel brings its own suggested range and colour map.
DisplayMapping resolveMapping(const PaneImage& pane, const DisplaySettings& settings, float exposure,
                              const std::optional<ValueRange>& autoRange);

// Channels of a 2D texture format that reads as floats (normalised or float formats); 0 for integer,
// depth and other formats, which must be read back another way.
int channelsOfFormat(GLint format);

// Uploads a CPU image (row 0 at the top) as RGBA32F; its rows stay top-first, so no flip on display.
void uploadImage(PaneImage& pane, const viz::Image& image);

// Makes a pane from one of the technique's intermediates. A 2D float texture is sampled directly;
// other textures (integer, depth, arrays, cube maps, 3D) are read back one layer at a time.
void makePane(PaneImage& pane, const viz::Intermediate& in, int layer);

// Draws PaneImages: shaders/ui/image.vert + image.frag over an empty vertex array.
class ImageDisplay {
public:
    ImageDisplay();
    void draw(const PaneImage& pane, const viz::ui::Rect& rect, glm::ivec2 framebuffer, const DisplayMapping& mapping,
              const viz::ui::ImageViewTransform& view = {}) const;

private:
    viz::gl::Program mProgram;
    viz::gl::VertexArray mVertexArray;
    viz::gl::Sampler mSampler;
};

}  // namespace airlight
