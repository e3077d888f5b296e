// A grid view's two title lines: what it shows ("Rank-N reconstruction error   [10/19]  minmax.reconstruction_error
// (stage minmax.rectify)   layer 1/6") and the note under it (the intermediate's note, the range and units
// it is shown over, the difference figures, the zoom). A plain function of the view and a few facts about
// the window, so tests write the expected text out by hand (tests/cpu/ui/view_title_test.cpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "debug/technique.h"
#include "ui/font.h"
#include "view_state.h"

namespace airlight {

struct ViewTitleFacts {
    bool haveOutput = false;    // a run has finished (else "(no view)" or "computing...")
    bool gpuTechnique = true;   // the current technique runs on the GPU
    int contentCount = 0;       // entries of the views list: final, L_air and the run's intermediates
    float exposure = 0.0f;      // the window's, in EV (the final image's note states it)
    const std::vector<viz::StageInfo>* stages = nullptr;  // the technique's: the stage publishing a view is named
    // While playing: the temporal views' running scores (TemporalMonitor::describe, describeError) and,
    // along a --path, the reference's frames.
    std::string temporalChange, temporalErrorChange;
    int referenceReady = 0, referenceTotal = 0;
    double referenceSecondsPerFrame = 0.0;
    std::string referenceError;
};

// {title, note}.
std::pair<std::string, std::string> viewTitle(const ViewState& v, const ViewTitleFacts& facts);

// What the title bar warns of after the title, in the warning colour. `early`: where the run stopped
// short of the complete algorithm ("   [stopped after ...]", from `stoppedEarly`, empty for a complete
// frame) and what the view shows in the chosen content's stead. `counts`: its negative pixels (only
// where its mapping marks them: in a signed quantity they are values), NaN and Inf pixels.
struct TitleWarnings {
    std::string early, counts;
};
TitleWarnings titleWarnings(const ViewState& v, const std::string& stoppedEarly, float exposure);

// The title bar's lines fitted to their widths (`width` for the first line up to the display toggle,
// `noteWidth` for the note): the warnings keep their room first (the title keeps at least 35 % of the
// line); the title and the note then keep their first sections whole ("  ..." for the rest) and where
// the run stopped loses whole words from its end (text_fit.h). The counts are always shown whole.
struct FittedTitle {
    std::string title, early, note;
    bool titleElided = false, noteElided = false;
};
FittedTitle fitTitleBar(const viz::ui::FontAtlas& font, const std::string& title, const TitleWarnings& warnings,
                        const std::string& note, float width, float noteWidth);

}  // namespace airlight
