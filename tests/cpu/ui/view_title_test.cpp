// A grid view's title lines (app/view_title.h) for each kind of view, the expected text written out by
// hand: the list position, the id and the stage that publishes it, the layer, the final image's exposure,
// the range a grey view is shown over, the difference figures, the zoom, the temporal views' scores and
// the reference's frames along a path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cpu/ui/synthetic_panel.h"
#include "temporal_monitor.h"
#include "text_fit.h"
#include "colour_bar.h"
#include "view_title.h"

namespace airlight {
namespace {

class ViewTitleTest : public ::testing::Test {
protected:
    ViewTitleTest() {
        stages = {{"minmax.rectify", "Rectify", "", {}, {"minmax.rectified"}, 1},
                  {"minmax.mipmap", "Min-max mipmap", "", {}, {"minmax.tree", "minmax.pyramid"}, 1}};
        facts.haveOutput = true;
        facts.contentCount = 19;
        facts.exposure = 1.5f;
        facts.stages = &stages;
    }
    static ViewState view(const std::string& id, const std::string& label, int shown) {
        ViewState v;
        v.content = id;
        v.pane.id = id;
        v.pane.label = label;
        v.pane.note = "the note";
        v.shown = shown;
        return v;
    }
    std::vector<viz::StageInfo> stages;
    ViewTitleFacts facts;
};

TEST_F(ViewTitleTest, BeforeAnyRunTheTitleSaysWhy) {
    facts.haveOutput = false;
    EXPECT_EQ(viewTitle(view("final", "Final image", 0), facts), std::make_pair(std::string("(no view)"), std::string()));
    facts.gpuTechnique = false;
    EXPECT_EQ(viewTitle(view("final", "Final image", 0), facts).first, "computing...");
}

TEST_F(ViewTitleTest, AnIntermediateNamesItsPlaceItsIdItsStageAndItsLayer) {
    ViewState v = view("minmax.tree", "Min-max mipmaps", 11);
    EXPECT_EQ(viewTitle(v, facts).first, "Min-max mipmaps   [12/19]  minmax.tree  (stage minmax.mipmap)");
    EXPECT_EQ(viewTitle(v, facts).second, "the note");
    v.pane.layers = 6;
    v.pane.layer = 2;
    EXPECT_EQ(viewTitle(v, facts).first, "Min-max mipmaps   [12/19]  minmax.tree  (stage minmax.mipmap)   layer 3/6");
    // An id no stage declares (a shared pass's) has no stage; an empty label falls back to the content.
    ViewState shared = view("minmax.shadow_map", "", 2);
    EXPECT_EQ(viewTitle(shared, facts).first, "minmax.shadow_map   [3/19]  minmax.shadow_map");
}

// An exposure that rounds to nothing reads "+0.0 EV", never "-0.0 EV" (auto exposure of a scene whose
// white is exactly 1 gave -0).
TEST_F(ViewTitleTest, AnExposureOfNothingHasNoSign) {
    for (const float e : {-0.0f, -0.04f, 0.0f, 0.04f}) {
        facts.exposure = e;
        EXPECT_NE(viewTitle(view("final", "Final image", 0), facts).second.find("(exposure +0.0 EV)"), std::string::npos) << e;
    }
    EXPECT_EQ(shortNumber(-0.0), "0");
    EXPECT_EQ(shortNumber(-0.25), "-0.25");
}

TEST_F(ViewTitleTest, TheFinalImageStatesTheExposureAndAGreyViewItsRange) {
    EXPECT_EQ(viewTitle(view("final", "Final image", 0), facts),
              std::make_pair(std::string("Final image   [1/19]"),
                             std::string("surface radiance * exp(-sigma_t d) + L_air   (exposure +1.5 EV)")));
    ViewState grey = view("minmax.rectified", "Rectified shadow map", 5);
    grey.pane.kind = viz::ViewKind::Scalar;
    grey.pane.mode = DisplayMode::Grey;
    grey.pane.rangeMin = 0.0f;
    grey.pane.rangeMax = 3.14159f;
    grey.pane.units = "radians";
    EXPECT_EQ(viewTitle(grey, facts).second, "the note   [0, 3.142] radians, scalar");
}

TEST_F(ViewTitleTest, DifferenceFiguresAndTheZoomComeFirstInTheNote) {
    ViewState v = view("airlight", "Airlight L_air", 1);
    v.error = viz::report::ErrorMetrics{};
    v.error->relativeL2 = 0.0123;
    v.error->maxAbsolute = 0.5;
    v.error->rmse = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(viewTitle(v, facts).second, "relative L2 0.0123   max |a - b| 0.5   RMSE n/a   |   the note");
    v.error.reset();
    v.differenceNote = "against the reference: computing it...";
    v.transform.zoom = 4.0;
    EXPECT_EQ(viewTitle(v, facts).second,
              "zoom 4x (wheel; drag to pan; 0 fits)   against the reference: computing it...   |   the note");
}

TEST_F(ViewTitleTest, TemporalViewsLeadWithTheirScoreAndThePathsReferenceFrames) {
    ViewState v = view(kTemporalErrorChangeId, "Error change per frame", 4);
    facts.contentCount = 9;
    facts.temporalErrorChange = "temporal RMS 0.012 over 5 pairs";
    facts.referenceReady = 2;
    facts.referenceTotal = 6;
    facts.referenceSecondsPerFrame = 1.5;
    EXPECT_EQ(viewTitle(v, facts).first,
              "Error change per frame: temporal RMS 0.012 over 5 pairs   reference frames 2/6, 1.5 s each   [5/9]");
    facts.referenceError = "reference: out of memory";
    EXPECT_EQ(viewTitle(v, facts).first,
              "Error change per frame: temporal RMS 0.012 over 5 pairs   reference failed: reference: out of memory   [5/9]");
    facts.referenceError.clear();
    facts.referenceReady = 6;
    EXPECT_EQ(viewTitle(v, facts).first, "Error change per frame: temporal RMS 0.012 over 5 pairs   [5/9]")
        << "every frame in: no count";
}

// The title bar's warnings: where the run stopped and what stands in, then negative pixels only where the
// view's mapping marks them (radiance, not a signed quantity), NaN and Inf.
TEST_F(ViewTitleTest, TheWarningsSayWhereTheRunStoppedAndCountOnlyWhatTheMappingMarks) {
    ViewState v = view("airlight", "Airlight L_air", 1);
    v.pane.mode = DisplayMode::HdrColour;
    EXPECT_EQ(titleWarnings(v, "", 0.0f).early, "");
    EXPECT_EQ(titleWarnings(v, "", 0.0f).counts, "") << "nothing to warn of";
    v.standIn = "shows L_air: this run makes no plane view";
    v.counts.negative = 5;
    v.counts.nan = 2;
    const TitleWarnings w = titleWarnings(v, "stopped after stage 2 of 5", 0.0f);
    EXPECT_EQ(w.early, "   [stopped after stage 2 of 5]   [shows L_air: this run makes no plane view]");
    EXPECT_EQ(w.counts, "  5 negative 2 NaN px");
    v.counts.inf = 1;
    v.counts.nan = 0;
    v.display.markNegative = 0;  // the user turned the marking off: negatives are not warned of
    EXPECT_EQ(titleWarnings(v, "", 0.0f).counts, "  1 Inf px");
    ViewState d = view("polyvol.signed_total", "Signed total", 9);
    d.pane.mode = DisplayMode::Signed;
    d.counts.negative = 400;
    EXPECT_EQ(titleWarnings(d, "", 0.0f).counts, "") << "negative values of a signed quantity are values";
}

// Fitted to its width: whole when it fits; when not, the warnings keep their room (the title at least
// 35 % of the line) and the whole line stays inside the width.
TEST_F(ViewTitleTest, ATitleTooLongForItsBarIsShortenedBeforeItsWarnings) {
    const viz::ui::FontAtlas& font = viz::ui::testing::testFont();
    const std::string title = "Rectified shadow map, picked slice   [6/19]  minmax.rectified (stage minmax.rectify)";
    const std::string note = "depth along each epipolar slice, light space, scene units 0 .. 40";
    const TitleWarnings warn{"   [stopped after stage 3 of 6]", "  12 NaN px"};
    const float all = font.measure(title + warn.early + warn.counts);
    const FittedTitle whole = fitTitleBar(font, title, warn, note, all + 1.0f, font.measure(note) + 1.0f);
    EXPECT_EQ(whole.title, title);
    EXPECT_EQ(whole.early, warn.early);
    EXPECT_EQ(whole.note, note);
    EXPECT_FALSE(whole.titleElided || whole.noteElided);

    // Room for the name and its place in the list, not for the id and stage: the title's later sections
    // give way first, "  ..." saying that more is shown on hover.
    const std::string head = "Rectified shadow map, picked slice   [6/19]  ...";
    const float width = font.measure(head + warn.early + warn.counts) + 1.0f;
    ASSERT_LT(width, all);
    const FittedTitle fit = fitTitleBar(font, title, warn, note, width, 0.5f * font.measure(note));
    EXPECT_TRUE(fit.titleElided);
    EXPECT_TRUE(fit.noteElided);
    EXPECT_EQ(fit.early, warn.early) << "the warning is kept whole while the title can give way";
    EXPECT_EQ(fit.title, head);
    EXPECT_LE(font.measure(fit.title + fit.early + warn.counts), width);
    EXPECT_LE(font.measure(fit.note), 0.5f * font.measure(note));

    // So narrow that the warnings alone would not fit: the title keeps 35 % of the line, the warning gives way.
    const float narrow = font.measure(warn.early + warn.counts);
    const FittedTitle tight = fitTitleBar(font, title, warn, note, narrow, 100.0f);
    EXPECT_GE(font.measure(tight.title), 0.2f * narrow);
    EXPECT_LE(font.measure(tight.title), 0.35f * narrow);
    EXPECT_NE(tight.early, warn.early);
    EXPECT_LE(font.measure(tight.title + tight.early + warn.counts), narrow + 1.0f);
}

// A title in sections ("name   [k/n]  id  (stage ...)"), narrowed step by step: whole while it fits, then
// its first sections followed by "  ...", then its name alone shortened in the middle; never wider than
// asked (each width checked against the font, an exhaustive loop over the widths).
TEST_F(ViewTitleTest, ANarrowTitleKeepsItsFirstSectionsWhole) {
    const viz::ui::FontAtlas& font = viz::ui::testing::testFont();
    const std::string title = "Distance d   [3/8]  reference.distance  (stage reference.trace)";
    const std::vector<std::string> heads = {"Distance d", "Distance d   [3/8]", "Distance d   [3/8]  reference.distance"};
    const float whole = font.measure(title);
    int sectionForms = 0;
    for (float w = whole + 2.0f; w >= font.measure("..."); w -= 1.0f) {  // "..." is the least it gives
        const std::string fit = elideSections(font, title, w);
        if (w >= whole) {
            EXPECT_EQ(fit, title);
            continue;
        }
        EXPECT_LE(font.measure(fit), w) << fit;
        const bool sectioned = std::any_of(heads.begin(), heads.end(), [&](const std::string& h) { return fit == h + "  ..."; });
        if (sectioned) {
            ++sectionForms;
            // The longest whole-section form that fits.
            for (const std::string& h : heads) {
                if (font.measure(h + "  ...") <= w) { EXPECT_GE(fit.size(), h.size() + 5) << fit; }
            }
        } else {
            EXPECT_GT(font.measure(heads[0] + "  ..."), w) << fit;  // only when even the name does not fit
            EXPECT_EQ(fit.find("[3/8]"), std::string::npos) << fit;
        }
    }
    EXPECT_GE(sectionForms, 3);
}

// Where the run stopped, narrowed: whole words cut from the end with "..." in their place, the opening
// word and the brackets kept, never wider than asked.
TEST_F(ViewTitleTest, ANarrowStoppedWarningLosesWholeWordsFromItsEnd) {
    const viz::ui::FontAtlas& font = viz::ui::testing::testFont();
    const std::string early = "   [stopped after stage 1/5 reference.trace]";
    const std::string stem = "   [stopped after stage 1/5 reference.trace";
    const float whole = font.measure(early), least = font.measure("   [stopped ...]");
    for (float w = whole + 2.0f; w >= least; w -= 1.0f) {
        const std::string fit = elideBracketWords(font, early, w);
        EXPECT_LE(font.measure(fit), w) << fit;
        if (w >= whole) {
            EXPECT_EQ(fit, early);
            continue;
        }
        ASSERT_GE(fit.size(), 5u);
        EXPECT_EQ(fit.substr(fit.size() - 5), " ...]") << fit;
        const std::string kept = fit.substr(0, fit.size() - 5);
        EXPECT_EQ(stem.rfind(kept, 0), 0u) << fit;                 // a start of the original...
        EXPECT_EQ(stem[kept.size()], ' ') << fit;                  // ...ending at a whole word
        EXPECT_EQ(kept.rfind("   [stopped", 0), 0u) << fit;
    }
    EXPECT_LE(font.measure(elideBracketWords(font, early, 0.5f * least)), 0.5f * least);
}

}  // namespace
}  // namespace airlight
