// The view grid's contents: each view's pane built from the last run, difference views and the runs of
// other techniques they need, and the grid edits (split, close, swap, step).
#include "gui_app.h"
#include "difference_pane.h"
#include "view_contents.h"

namespace airlight {

int GuiApp::contentCount() const { return airlight::contentCount(mOutput); }

std::vector<std::string> GuiApp::shownContents() const {
    // What each view chose and what it shows in its stead: a run stepped to a stage before the final frame
    // shows that stage's views in the final frame's and L_air's panes, and those that are drawn on demand
    // (slices.plane, the planes' orbit view) must then be asked for.
    std::vector<std::string> shown;
    for (int id : mGrid.layout.views())
        if (const auto it = mGrid.views.find(id); it != mGrid.views.end()) {
            shown.push_back(it->second.content);
            if (!it->second.pane.id.empty() && it->second.pane.id != it->second.content) shown.push_back(it->second.pane.id);
        }
    return shown;
}

std::string GuiApp::contentId(int index) const { return airlight::contentId(mOutput, index); }

std::string GuiApp::contentLabel(int index) const { return airlight::contentLabel(mOutput, index); }

int GuiApp::contentIndexOf(const std::string& id) const { return airlight::contentIndexOf(mOutput, id); }

std::string GuiApp::lessonViewCaption(const std::string& id) const {
    const int index = contentIndexOf(id);
    const std::string label = index < 0 ? std::string() : contentLabel(index);
    return label.empty() ? id : label;  // as the view title falls back to the id
}

ViewState& GuiApp::focusedView() {
    if (!mGrid.views.count(mState.focusedView)) mState.focusedView = mGrid.layout.views().front();
    return mGrid.views[mState.focusedView];
}

bool GuiApp::isScreenSpace(const ViewState& v) const {
    return v.pane.texture != 0 && mOutputSize.x > 0 && v.pane.size == mOutputSize && !isOrbitView(v);
}

void GuiApp::buildPane(ViewState& v) {
    const std::string before = v.pane.id;
    v.pane = {};
    v.error.reset();
    v.differenceNote.clear();
    v.standIn.clear();
    v.shown = -1;
    if (!mHaveOutput) return;
    const auto& all = mOutput.intermediates;
    std::vector<std::string> elsewhere;  // what the other views chose and show (those built before this one)
    for (int id : mGrid.layout.views())
        if (const auto it = mGrid.views.find(id); it != mGrid.views.end() && &it->second != &v) {
            elsewhere.push_back(it->second.content);
            elsewhere.push_back(it->second.pane.id);
        }
    const ShownContent choice = shownContent(technique(), mOutput, v.content, v.index, elsewhere);
    const std::string& content = choice.content;
    const int index = choice.index;
    v.standIn = choice.standIn;
    if (index >= 0) v.index = index;
    // The two radiance images every run has: contents 0 (final) and 1 (L_air).
    const auto radiancePane = [&](int shown, const char* id, const char* note, const viz::Image& image) {
        v.shown = shown;
        v.pane.id = id;
        v.pane.label = contentLabel(shown);
        v.pane.note = note;
        v.pane.units = "radiance";
        v.pane.kind = viz::ViewKind::Colour;
        v.pane.mode = DisplayMode::HdrColour;
        uploadImage(v.pane, image);
    };
    if (content == "final") {
        radiancePane(0, "final", "surface radiance * exp(-sigma_t d) + L_air", mOutput.final);
    } else if (content == "airlight") {
        radiancePane(1, "airlight", "in-scattered radiance along each eye ray, before the surface term",
                     mOutput.airlight);
    } else {
        v.shown = index + 2;
        makePane(v.pane, all[std::size_t(index)], v.layer);
        v.layer = v.pane.layer;
    }
    // A view that moves to other content starts on that content's channel (a multi-quantity pane: its
    // first quantity); one restored or re-run keeps the channel it has, unless that shows nothing here.
    const bool unusable = !v.pane.channelInfo.empty() && v.display.channel != Channel::Rgb &&
                          !declaredChannel(v.pane, v.display.channel);
    if ((!before.empty() && before != v.pane.id) || unusable) v.display.channel = defaultChannel(v.pane);
    if (v.display.difference != DifferenceMode::Off && (content == "final" || content == "airlight"))
        makeDifference(v, content);
    else if (v.display.difference != DifferenceMode::Off)
        v.differenceNote = "no difference: this view shows " + content + " (difference is for the final frame and L_air)";
}

void GuiApp::makeDifference(ViewState& v, const std::string& content) {
    const DisplaySettings& d = v.display;
    const viz::Image& mine = content == "final" ? mOutput.final : mOutput.airlight;
    const DifferenceRuns::Run* other = otherRun(d.against);
    if (!other) {
        v.differenceNote = mReduced ? "difference to " + d.against + ": after the interaction"
                                    : "difference to " + d.against + ": computing it...";
        return;
    }
    if (!other->failure.empty()) {
        v.differenceNote = d.against + " failed: " + firstLine(other->failure);
        return;
    }
    const viz::Image& theirs = content == "final" ? other->final : other->airlight;
    if (mine.empty() || theirs.empty() || mine.width != theirs.width || mine.height != theirs.height ||
        mine.channels != theirs.channels) {
        v.differenceNote = "difference to " + d.against + ": no image of the same size yet";
        return;
    }
    v.error = viz::report::compareImages(mine, theirs);
    const viz::Image diff = differenceImage(mine, theirs, d.difference);
    PaneImage pane = differencePane(v.pane, diff, d.difference, d.against, other->held, technique().id());
    uploadImage(pane, diff);
    v.pane = std::move(pane);
}

const DifferenceRuns::Run* GuiApp::otherRun(const std::string& id) {
    if (mReduced) return nullptr;
    if (id == technique().id()) {
        mSelfRun = {"", mOutput.airlight, mOutput.final, "", "", 0, false};
        return &mSelfRun;
    }
    return mDifferenceRuns.get(id, differenceRequest(id));
}

DifferenceRequest GuiApp::differenceRequest(const std::string& id) {
    DifferenceRequest r{&mScene, mController.camera(), mOutputSize, givenSettings(id), mAnimation.playing};
    try {
        r.settings = completedOtherSettings(id);
    } catch (const std::exception&) {
        // An id that makes no technique: DifferenceRuns::get records the failure.
    }
    return r;
}

viz::Settings GuiApp::givenSettings(const std::string& id) const {
    viz::Settings given = mSession.settings.count(id) ? mSession.settings.at(id) : viz::Settings{};
    if (const auto options = mOptions.settings.find(id); options != mOptions.settings.end())
        for (const auto& [name, value] : options->second) given[name] = value;
    return given;
}

viz::Settings GuiApp::completedOtherSettings(const std::string& id) {
    std::string ignored;
    return settingsFor(mRuns.runner(Consumer::Others, id).technique(), givenSettings(id), ignored);
}

void GuiApp::runDueGpuOthers() {
    for (const std::string& id : mDifferenceRuns.runDue([this](const std::string& id) { return differenceRequest(id); }))
        refreshDifferenceViews(id);
}

void GuiApp::pollOtherWorker() {
    if (const std::optional<std::string> id = mDifferenceRuns.poll()) refreshDifferenceViews(*id);
}

void GuiApp::refreshDifferenceViews(const std::string& against) {
    for (auto& [vid, v] : mGrid.views)
        if (v.display.difference != DifferenceMode::Off && v.display.against == against) refreshView(v);
}

void GuiApp::refreshView(ViewState& v) {
    buildPane(v);
    if (mReduced) {
        // During an interaction the frames are smaller and short-lived: no readback.
        v.values = {};
        updateStatistics(v);
    } else {
        readBackValues(v);
    }
}

void GuiApp::refreshPanes() {
    mMarkerCache.clear();
    mInspector.forgetRun();
    // Automatic exposure from the final image, or from L_air while a stopped run has none yet.
    const viz::Image& exposed = mOutput.final.empty() ? mOutput.airlight : mOutput.final;
    if (mHaveOutput && !mState.exposureSet && !exposed.empty()) {
        mState.exposure = std::round(std::log2(autoExposure(exposed)) / kExposureStep) * kExposureStep;
        mState.exposureSet = true;
    }
    for (auto& [id, v] : mGrid.views) refreshView(v);
}

void GuiApp::stepView(int delta) {
    if (!mHaveOutput) return;
    ViewState& v = focusedView();
    const int n = contentCount();
    selectView((((v.shown < 0 ? 1 : v.shown) + delta) % n + n) % n);
}

void GuiApp::selectView(int index) {
    if (!mHaveOutput || index < 0 || index >= contentCount()) return;
    ViewState& v = focusedView();
    v.content = contentId(index);
    v.index = index - 2;
    v.layer = 0;
    v.transform.fit();
    refreshView(v);
}

void GuiApp::stepLayer(int delta) {
    ViewState& v = focusedView();
    if (v.pane.layers <= 1) return;
    v.layer = (v.pane.layer + delta + v.pane.layers) % v.pane.layers;
    refreshView(v);
}

void GuiApp::splitFocused(SplitAxis axis) {
    const int id = mGrid.split(mState.focusedView, axis);
    if (id < 0) return;
    ViewState& v = mGrid.views.at(id);
    const int shown = mGrid.views.at(mState.focusedView).shown;
    if (mHaveOutput) {
        const int next = (shown < 0 ? 1 : shown + 1) % contentCount();
        v.content = contentId(next);
        v.index = next - 2;
    }
    mState.focusedView = id;
    refreshView(v);
}

void GuiApp::closeFocused() {
    const int next = mGrid.close(mState.focusedView);
    if (next < 0) {
        mNotice = "the last view stays open";
        return;
    }
    mState.focusedView = next;
}

void GuiApp::swapFocused(int step) { mGrid.swap(mState.focusedView, step); }

void GuiApp::toggleDifference() {
    ViewState& v = focusedView();
    if (v.pane.id != "final" && v.pane.id != "airlight" && v.display.difference == DifferenceMode::Off) {
        mNotice = "difference views are for the final frame and L_air";
        return;
    }
    v.display.difference = v.display.difference == DifferenceMode::Off ? DifferenceMode::Absolute : DifferenceMode::Off;
    refreshView(v);
}

}  // namespace airlight
