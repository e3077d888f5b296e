// The comparison grid (G) and exporting a view (E) or the window (F12).
#include "gui_app.h"

namespace airlight {

void GuiApp::toggleComparison() {
    if (mComparison.isOpen()) {
        mComparison.close();
        return;
    }
    openComparison(mIds);
}

void GuiApp::openComparison(const std::vector<std::string>& ids) {
    viz::scene::Scene scene = mScene;
    scene.camera = mController.camera();
    try {
        mComparison.open(scene, {mOptions.width, mOptions.height}, ids);
    } catch (const std::exception& e) {
        mError = std::string("comparison: ") + e.what();
        mComparison.close();
    }
}

void GuiApp::showLessonComparison(const std::vector<std::string>& techniques) {
    mComparison.close();
    if (techniques.empty()) return;
    std::vector<std::string> ids = {"reference"};
    ids.insert(ids.end(), techniques.begin(), techniques.end());
    openComparison(ids);
}

ComparisonGrid::RunTechnique GuiApp::comparisonRunner() {
    return [this](const std::string& id, const viz::scene::Scene& scene, glm::ivec2 size, int frame) {
        RunScheduler& runner = mRuns.runner(Consumer::Others, id);
        runner.invalidate();  // the grid times whole runs: nothing carried over from the last one
        viz::FrameOutput out = runner.run(scene, size.x, size.y, completedOtherSettings(id), {}, {}, frame);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return out;
    };
}

void GuiApp::runComparisonTechniques() { mComparison.runTechniques(comparisonRunner()); }

void GuiApp::drawComparison(DrawList& dl, const Rect& area) {
    const float line = mFont->lineHeight(), pad = 4.0f * mScale;
    const int n = int(mComparison.tiles().size());
    // One more cell for the plot of error against time.
    const int cells = n + 1;
    const int cols = int(std::ceil(std::sqrt(double(cells)))), rows = (cells + cols - 1) / cols;
    const glm::vec2 cell{area.size().x / float(cols), area.size().y / float(rows)};
    const bool playing = mComparison.playing();
    dl.textClipped({area.min.x, area.min.y - line},
                   playing ? "comparison (G), playing (P): frame " + std::to_string(mComparison.playedFrames()) +
                                 ", run time and the change of L_air per frame (along a --path, its error's flicker "
                                 "against the reference's frames; the plot: the still frame; P stops)"
                           : std::string("comparison (G): L_air at the reference's exposure, time of a warm run and "
                                         "relative L2 against the reference"),
                   kAccent, area.max.x);
    {
        // The plot takes the rest of the last row.
        const glm::vec2 at = area.min + glm::vec2(float(n % cols), float(n / cols)) * cell;
        const Rect box{at + pad, at + glm::vec2(float(cols - n % cols), 1.0f) * cell - pad};
        viz::plot::drawPlot(dl, box, mComparison.errorAgainstTime());
        mScreen.placeView({"comparison.error_vs_time", "relative L2 against time", box, -1});
    }
    for (int i = 0; i < n; ++i) {
        ComparisonTile& tile = mComparison.tiles()[std::size_t(i)];
        const glm::vec2 at = area.min + glm::vec2(float(i % cols), float(i / cols)) * cell;
        const Rect box{at + pad, at + cell - glm::vec2(pad, pad + 2.0f * line)};
        const Rect image = fitImage(box, tile.pane.size);
        if (tile.pane.texture != 0) {
            DisplayMapping shared;
            shared.exposure = mComparison.exposure();
            mPaneDraws.push_back({image, &tile.pane, nullptr, shared});
        } else if (tile.failure.empty()) {
            dl.textClipped({box.min.x + 4.0f * mScale, box.min.y + 4.0f * mScale}, mComparison.waitingText(), kDim,
                           box.max.x);
        }
        std::string caption = tile.technique;
        std::string figures = tile.failure.empty()
            ? (tile.pane.texture == 0 ? std::string("")
               : tile.technique == "reference"
                   ? std::string(!playing ? "ground truth"
                                 : mAnimation.reference.total() > 0
                                     ? "still frame; path frames " + std::to_string(mAnimation.reference.ready()) + "/" +
                                           std::to_string(mAnimation.reference.total())
                                     : "ground truth, still frame")
               // Playing: the flicker against the reference's path frames once known (the figure to rank
               // by, where a tile has room for one), else the change of L_air.
               : playing ? (tile.temporal.errorPairs() > 0
                                ? format("%.0f ms", tile.playMilliseconds) + format("  flicker %.3g", tile.temporal.errorScore())
                                : format("%.1f ms", tile.playMilliseconds) + format("   change %.3g", tile.temporal.score()))
                         : format("%.1f ms", tile.milliseconds) + "   " + tileErrorText(tile.error))
            : "failed: " + firstLine(tile.failure);
        if (tile.error.nanPixels + tile.error.infPixels > 0)
            figures += "   " + std::to_string(tile.error.nanPixels + tile.error.infPixels) + " NaN/Inf px";
        float captionX = box.min.x;
        if (tile.technique != "reference") {
            // The colour of its point in the error-against-time plot (whose legend a small cell leaves out).
            const float mark = line - 6.0f * mScale;
            dl.rect({{captionX, box.max.y + 5.0f * mScale}, {captionX + mark, box.max.y + 5.0f * mScale + mark}},
                    viz::plot::categoricalColour(i));
            captionX += mark + 4.0f * mScale;
        }
        dl.textClipped({captionX, box.max.y + 2.0f}, caption, kText, at.x + cell.x - pad);
        dl.textClipped({box.min.x, box.max.y + 2.0f + line}, figures, kDim, at.x + cell.x - pad);
    }
}

std::string GuiApp::exportStem(const std::string& what) {
    // A file's scene is named by the file (the glTF's own scene name may be another scene's).
    const std::string scene = isSceneFile(mOptions.scene) ? std::filesystem::path(mOptions.scene).stem().string() : mScene.name;
    std::string name = scene + "-" + technique().id() + "-" + what;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    std::error_code ec;
    std::filesystem::create_directories(mOptions.exportDir, ec);
    return (std::filesystem::path(mOptions.exportDir) / name).string();
}

bool GuiApp::focusedViewImage(viz::Image& image, float& exposure) {
    ViewState& v = focusedView();
    if (!mHaveOutput || v.pane.texture == 0) return false;
    // The view's CPU copy, read back after each run (not during a drag's reduced runs: then read now).
    if (v.values.empty()) readBackValues(v);
    if (v.values.empty()) return false;
    const viz::Image& values = v.values;
    const DisplayMapping m = resolveMapping(v.pane, v.display, mExposure, v.measured);
    const bool colour = m.mode == DisplayMode::HdrColour || m.mode == DisplayMode::RangeColour;
    image = colour ? values : viz::toDisplay(values, m.lo, m.hi);
    exposure = colour ? std::exp2(m.exposure) : 1.0f;
    return true;
}

void GuiApp::exportView() {
    if (mAnimation.playing) {
        toggleRecording();
        return;
    }
    const PaneImage& pane = focusedView().pane;
    viz::Image shown;
    float exposure = 1.0f;
    if (!focusedViewImage(shown, exposure)) {
        mNotice = "nothing to export: the view holds no image";
        return;
    }
    const std::string stem = exportStem(pane.id.empty() ? "view" : pane.id);
    try {
        viz::writeImage(focusedView().values, stem + ".exr");
        viz::writeImage(shown, stem + ".png", exposure);
        mNotice = "exported " + stem + ".exr and .png";
    } catch (const viz::InputError& e) {
        mNotice = e.what();
    }
}

void GuiApp::toggleRecording() {
    if (mAnimation.recorder.recording()) {
        stopRecording();
        return;
    }
    const PaneImage& pane = focusedView().pane;
    mAnimation.recorder.start(exportStem(pane.id.empty() ? "view" : pane.id) + ".gif");
    mAnimation.recordStart = mAnimation.clock;
    mNotice = "recording the focused view: E or P stops and writes the GIF";
}

void GuiApp::stopRecording() {
    if (!mAnimation.recorder.recording()) return;
    // The animation's own clock: frames over the seconds it played (1/30 s a frame under automation).
    const double seconds = mAnimation.clock - mAnimation.recordStart;
    const int fps = seconds > 0.0 ? int(std::lround(double(mAnimation.recorder.frames()) / seconds)) : 25;
    mNotice = mAnimation.recorder.finish(fps);
}

void GuiApp::exportWindow() {
    const std::string path = exportStem("window") + ".png";
    try {
        writeScreenshot(path);
        mNotice = "wrote " + path;
    } catch (const viz::InputError& e) {
        mNotice = e.what();
    }
}

}  // namespace airlight
