#include "lesson_player.h"
#include "lesson_prose.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "ray_inspection.h"
#include "techniques/registry.h"

namespace airlight {

namespace {

using viz::ui::DrawList;
using viz::ui::Rect;

using namespace viz::ui::theme;  // the panel's colours
constexpr double kMaxStepSeconds = 0.1;  // an animation advances at most this much per frame

bool sameCamera(const viz::scene::Camera& a, const viz::scene::Camera& b) {
    // The controller renormalises directions: allow for the last bits.
    const auto near = [](glm::dvec3 p, glm::dvec3 q) { return glm::length(p - q) <= 1e-9 * (1.0 + glm::length(q)); };
    return near(a.position, b.position) && near(a.forward, b.forward) && near(a.up, b.up) && a.yfov == b.yfov &&
           a.znear == b.znear && a.zfar == b.zfar;
}

bool sameLight(const viz::scene::Light& a, const viz::scene::Light& b, bool placement) {
    return a.type == b.type && a.colour == b.colour && a.intensity == b.intensity &&
           (!placement || (a.position == b.position && a.direction == b.direction));
}

}  // namespace

LessonPlayer::LessonPlayer(std::string path, glm::ivec2 sizeOverride)
    : mPath(std::move(path)), mSizeOverride(sizeOverride) {
    open();
}

void LessonPlayer::open() {
    mLoadError.clear();
    try {
        mLesson = parseLesson(mPath);
    } catch (const viz::InputError& e) {
        mLesson.reset();
        mLoadError = e.what();
    }
    if (mLesson) mStep = std::clamp(mStep, 0, int(mLesson->steps.size()) - 1);
    mDue = true;
}

void LessonPlayer::restore(int step, bool tryIt) {
    mStep = mLesson ? std::clamp(step, 0, int(mLesson->steps.size()) - 1) : 0;
    mTryIt = tryIt;
    mRestoreTryIt = tryIt;
    mDue = true;
}

void LessonPlayer::saveTo(SessionState& session) const {
    session.lesson = mPath;
    session.lessonStep = mStep;
    session.lessonTryIt = mTryIt;
}

std::vector<std::string> LessonPlayer::rightViews() const {
    std::vector<std::string> views;
    if (const LessonStep* s = step())
        for (const std::string& v : s->views)
            if (v != "final") views.push_back(v);
    if (views.empty()) views.push_back("airlight");
    return views;
}

void LessonPlayer::applyStep(LessonHost& host) {
    mDue = false;
    mStepError.clear();
    mWanted.reset();
    mPlaying = false;
    mTime = 0.0;
    mScroll = 0.0f;
    mSubstepParam.clear();
    const LessonStep* s = step();
    if (!s) return;
    try {
        // The scene is loaded again whenever it is not the step's, so its own camera, medium and
        // lights are known exactly (the window's may have been changed).
        if (!mBase || mBase->scene != s->scene || host.lessonWindowState().scene != s->scene) {
            mBase.reset();
            host.loadLessonScene(s->scene);
            mBase = host.lessonWindowState();
            mBase->scene = s->scene;
        }
        LessonWindowState w = *mBase;
        w.technique = s->technique;
        w.size = {s->width, s->height};
        const auto technique = viz::makeTechnique(s->technique);
        w.settings = viz::completeSettings(*technique, s->settings);
        const auto& stages = technique->stages();
        w.stage = int(stages.size()) - 1;
        for (int i = 0; i < int(stages.size()); ++i)
            if (stages[std::size_t(i)].id == s->stage) w.stage = i;
        w.views = rightViews();
        w.view = w.views.front();
        w.inspect = s->inspect;
        if (mSizeOverride.x > 0 && mSizeOverride.y > 0) {
            if (w.inspect) w.inspect = *w.inspect * mSizeOverride / w.size;
            w.size = mSizeOverride;
        }
        if (w.inspect && (w.inspect->x >= w.size.x || w.inspect->y >= w.size.y))
            throw viz::InputError("inspect (" + std::to_string(w.inspect->x) + ", " + std::to_string(w.inspect->y) +
                                  ") is outside the " + std::to_string(w.size.x) + "x" + std::to_string(w.size.y) + " image");
        // Inspecting a pixel points the technique's per-ray views at it (pick_x, pick_y): part of the step.
        if (w.inspect) (void)pickPixel(*technique, w.settings, *w.inspect);
        if (s->animation.kind == LessonAnimation::Kind::Substeps) {
            mSubstepParam = stages[std::size_t(w.stage)].substepParam;
            mSubstepValues = technique->substepValues(w.stage, w.settings);
            mSubstepStage = w.stage;
            mSubstepShown = int(mSubstepValues.size());
        }
        if (s->animation.kind == LessonAnimation::Kind::LightOrbit) {
            if (w.lights.empty()) throw viz::InputError("light orbit: the scene has no light");
            (void)orbitLight(w.lights[0], w.orbitTarget, 0.5);  // an area light fails here, not mid-animation
            mOrbitCentre = w.orbitTarget;
        }
        host.applyLessonWindowState(w);
        host.showLessonComparison(s->compare);
        mWanted = w;
        if (mRestoreTryIt) host.restoreSessionOverStep();
        else if (s->animation.kind != LessonAnimation::Kind::None) {
            mPlaying = true;  // a step's animation plays at once, from its first frame (sub-step 1)
            animate(host);
        }
    } catch (const viz::InputError& e) {
        std::string what = e.what();
        // Messages from the lesson parser already name the file and line.
        if (what.rfind(mPath + ":", 0) != 0) what = mPath + ":" + std::to_string(s->line) + ": step '" + s->title + "': " + what;
        mStepError = what;
    }
    mRestoreTryIt = false;
}

void LessonPlayer::animate(LessonHost& host) {
    const LessonStep* s = step();
    if (!s || !mWanted || s->animation.kind == LessonAnimation::Kind::None) return;
    const double t = std::clamp(mTime / s->animation.seconds, 0.0, 1.0);
    if (s->animation.kind == LessonAnimation::Kind::Substeps && !mSubstepParam.empty() && !mSubstepValues.empty()) {
        // Sub-step k of N for the k-th Nth of the time; the end shows them all (the last value). N: as many
        // as the last run counted where that is fewer (a walk's nodes).
        const int count = std::clamp(host.lessonSubstepCount(mSubstepStage), 1, int(mSubstepValues.size()));
        mSubstepShown = count;
        const int k = t >= 1.0 ? count : std::clamp(1 + int(t * double(count)), 1, count);
        host.setLessonSetting(mSubstepParam, k == count ? mSubstepValues.back() : mSubstepValues[std::size_t(k - 1)]);
    } else if (s->animation.kind == LessonAnimation::Kind::LightOrbit && !mWanted->lights.empty()) {
        host.setLessonLight(orbitLight(mWanted->lights[0], mOrbitCentre, t));
    }
}

bool LessonPlayer::matches(const LessonWindowState& now) const {
    if (!mWanted) return false;
    const LessonWindowState& w = *mWanted;
    const LessonStep* s = step();
    const bool substeps = s && s->animation.kind == LessonAnimation::Kind::Substeps;
    const bool orbit = s && s->animation.kind == LessonAnimation::Kind::LightOrbit;
    // The animated parameter and light are part of the step at any point of the animation.
    viz::Settings a = now.settings, b = w.settings;
    if (substeps) a.erase(mSubstepParam), b.erase(mSubstepParam);
    if (now.lights.size() != w.lights.size()) return false;
    for (std::size_t i = 0; i < w.lights.size(); ++i)
        if (!sameLight(now.lights[i], w.lights[i], !(orbit && i == 0))) return false;
    const std::vector<std::string> views = rightViews();
    return now.scene == w.scene && now.technique == w.technique && now.size == w.size && a == b &&
           now.stage == w.stage && std::find(views.begin(), views.end(), now.view) != views.end() &&
           now.inspect == w.inspect && sameCamera(now.camera, w.camera) && now.medium.sigma_s == w.medium.sigma_s &&
           now.medium.sigma_a == w.medium.sigma_a && now.medium.g == w.medium.g;
}

void LessonPlayer::update(LessonHost& host, double dt) {
    const std::vector<std::pair<Action, std::string>> actions = std::move(mActions);
    mActions.clear();
    const int steps = mLesson ? int(mLesson->steps.size()) : 0;
    for (const auto& [action, argument] : actions) {
        switch (action) {
            case Action::Previous:
                if (mStep > 0) --mStep, mDue = true;
                break;
            case Action::Next:
                if (mStep + 1 < steps) ++mStep, mDue = true;
                break;
            case Action::Back: mDue = true; break;
            case Action::ToggleTryIt:
                mTryIt = !mTryIt;
                if (!mTryIt) mDue = true;  // leaving try-it mode shows the step again
                break;
            case Action::PlayPause: {
                const LessonStep* s = step();
                if (!s || s->animation.kind == LessonAnimation::Kind::None || !mWanted) break;
                if (!mPlaying && mTime >= s->animation.seconds) mTime = 0.0;  // finished: play again
                mPlaying = !mPlaying;
                break;
            }
            case Action::Reload: open(); break;
            case Action::ShowView: host.showLessonView(argument); break;
        }
    }
    if (mDue && mLesson) applyStep(host);
    if (mPlaying) {
        if (const LessonStep* s = step()) {
            mTime = std::min(mTime + std::clamp(dt, 0.0, kMaxStepSeconds), s->animation.seconds);
            animate(host);
            if (mTime >= s->animation.seconds) mPlaying = false;
        } else {
            mPlaying = false;
        }
    }
    const LessonWindowState now = host.lessonWindowState();
    mShownView = now.view;
    mMatches = matches(now);
    // A change outside try-it mode is the student trying something: say so rather than undo it. Either
    // way the animation stops there (it would move what the student is looking at).
    if (!mMatches && mWanted && !mTryIt) mTryIt = true;
    if (!mMatches) mPlaying = false;
}

bool LessonPlayer::onKey(int key, bool repeat) {
    if (repeat && key != GLFW_KEY_PAGE_UP && key != GLFW_KEY_PAGE_DOWN)
        return key == GLFW_KEY_T || key == GLFW_KEY_B || (key == GLFW_KEY_SPACE && step() &&
                                                          step()->animation.kind != LessonAnimation::Kind::None);
    switch (key) {
        case GLFW_KEY_PAGE_UP: mActions.push_back({Action::Previous, {}}); return true;
        case GLFW_KEY_PAGE_DOWN: mActions.push_back({Action::Next, {}}); return true;
        case GLFW_KEY_T: mActions.push_back({Action::ToggleTryIt, {}}); return true;
        case GLFW_KEY_B: mActions.push_back({Action::Back, {}}); return true;
        case GLFW_KEY_SPACE: {
            const LessonStep* s = step();
            if (!s || s->animation.kind == LessonAnimation::Kind::None) return false;
            mActions.push_back({Action::PlayPause, {}});
            return true;
        }
        default: return false;
    }
}

void LessonPlayer::scroll(float lines) { mScroll -= lines * 3.0f * mLine; }

float LessonPlayer::panelWidth(float windowWidth, float scale) {
    return std::clamp(0.3f * windowWidth, 280.0f * scale, 480.0f * scale);
}


void LessonPlayer::draw(const LessonHost& host, viz::ui::Context& ui, DrawList& dl, DrawList& background, float scale) {
    const Rect& area = mArea;
    if (area.size().x <= 0.0f || area.size().y <= 0.0f) return;
    const viz::ui::FontAtlas& font = dl.font();
    const float line = font.lineHeight(), pad = 10.0f * scale;
    mLine = line;
    const float left = area.min.x + pad, width = area.size().x - 2.0f * pad;
    background.rect(area, ui.style().panel);
    background.rect({area.min, {area.min.x + 2.0f * scale, area.max.y}}, kRule);
    float y = area.min.y + pad;
    const auto wrapped = [&](const std::string& text, SpanStyle style) {
        y += drawLessonText(dl, text, style, {left, y}, width, scale);
    };
    // A row of buttons side by side: each in a frameless panel of its own (the toolkit stacks rows).
    const float rowH = ui.rowHeight() + 2.0f * 4.0f * scale;
    const auto buttons = [&](const std::vector<std::string>& labels, std::vector<bool>& pressed) {
        const float w = (area.size().x - pad) / float(labels.size());
        for (std::size_t i = 0; i < labels.size(); ++i) {
            const Rect cell{{area.min.x + pad * 0.5f + float(i) * w, y}, {area.min.x + pad * 0.5f + float(i + 1) * w, y + rowH}};
            ui.beginPanel("##lesson." + std::to_string(i), cell);
            pressed.push_back(ui.button(labels[i]));
            ui.endPanel();
        }
        y += rowH;
    };

    wrapped(mLesson ? mLesson->title : std::string("Lesson"), SpanStyle::Heading);
    if (!mLesson) {
        y += 0.5f * line;
        wrapped(mLoadError, SpanStyle::Normal);
        dl.rect({{left - 4.0f * scale, area.min.y + pad + line}, {left - 2.0f * scale, y}}, kError);
        y += 0.5f * line;
        std::vector<bool> pressed;
        buttons({"Reload lesson (fix the file first)"}, pressed);
        if (pressed[0]) mActions.push_back({Action::Reload, {}});
        y += 0.5f * line;
        wrapped("The window works as usual meanwhile.", SpanStyle::Normal);
        return;
    }
    const LessonStep& s = mLesson->steps[std::size_t(mStep)];
    dl.text({left, y}, "step " + std::to_string(mStep + 1) + " of " + std::to_string(mLesson->steps.size()), kDim);
    y += line + 2.0f * scale;
    wrapped(s.title, SpanStyle::Strong);
    {
        // What the step sets, as the handout prints it.
        std::string state = s.technique + " on " + s.scene;
        if (!s.stage.empty()) state += ", stopped after " + s.stage;
        if (mStepParamsFor != s.technique) {  // drawn every frame: the technique's declarations once per step
            mStepParams = viz::makeTechnique(s.technique)->params();
            mStepParamsFor = s.technique;
        }
        for (const auto& [name, value] : s.settings) state += ", " + viz::settingText(mStepParams, name, value);
        y += drawLessonText(dl, state, SpanStyle::Dim, {left, y}, width, scale);
    }
    y += 4.0f * scale;
    {
        std::vector<bool> pressed;
        buttons({"< Previous (PgUp)", "Next (PgDn) >"}, pressed);
        if (pressed[0]) mActions.push_back({Action::Previous, {}});
        if (pressed[1]) mActions.push_back({Action::Next, {}});
    }
    {
        // Try it, and how the window stands against the step.
        const Rect cell{{area.min.x + pad * 0.5f, y}, {area.min.x + pad * 0.5f + 0.5f * (area.size().x - pad), y + rowH}};
        ui.beginPanel("##lesson.tryit", cell);
        bool tryIt = mTryIt;
        if (ui.checkbox("Try it (T)", tryIt)) mActions.push_back({Action::ToggleTryIt, {}});
        ui.endPanel();
        const std::string state = !mStepError.empty() ? "step not applied" : mMatches ? "showing the step" : "changed from the step";
        dl.textClipped({cell.max.x + 4.0f * scale, y + 0.5f * (rowH - line)}, state, mMatches ? kDim : kAccent, area.max.x - pad);
        y += rowH;
        if (!mMatches || mTryIt) {
            std::vector<bool> pressed;
            buttons({"Back to the step (B)"}, pressed);
            if (pressed[0]) mActions.push_back({Action::Back, {}});
        }
    }
    if (s.animation.kind != LessonAnimation::Kind::None && mWanted) {
        std::vector<bool> pressed;
        buttons({mPlaying ? "Pause (Space)" : "Play (Space)"}, pressed);
        if (pressed[0]) mActions.push_back({Action::PlayPause, {}});
        const float fraction = float(std::clamp(mTime / s.animation.seconds, 0.0, 1.0));
        std::string progress = "animation: " + describeAnimation(s.animation);
        if (!mMatches) progress = "the animation plays on the step's state (B)";
        const int count = mSubstepShown;
        if (!mSubstepParam.empty() && count > 0)
            progress += ", " + std::to_string(fraction >= 1.0f ? count : std::clamp(1 + int(fraction * float(count)), 1, count)) +
                        "/" + std::to_string(count);
        dl.textClipped({left, y}, progress, kDim, area.max.x - pad);
        y += line;
        dl.rect({{left, y + scale}, {left + width, y + 4.0f * scale}}, kRule);
        dl.rect({{left, y + scale}, {left + fraction * width, y + 4.0f * scale}}, kAccent);
        y += 8.0f * scale;
    }
    {
        // The step's views: the grid shows up to three beside the final frame; a click focuses one (or shows
        // it in the focused view when it is not in the grid).
        const std::vector<std::string> views = rightViews();
        if (views.size() > 1) {
            dl.text({left, y}, "this step's views (in the grid; a click focuses one):", kDim);
            y += line;
            for (std::size_t i = 0; i < views.size(); ++i) {
                const Rect cell{{area.min.x + pad * 0.5f, y}, {area.max.x - pad * 0.5f, y + rowH}};
                ui.beginPanel("##lesson.view." + std::to_string(i), cell);
                const bool shown = views[i] == mShownView;
                // The window's caption of the view: one name per view everywhere.
                if (ui.button((shown ? "focused: " : "show ") + host.lessonViewCaption(views[i]))) mActions.push_back({Action::ShowView, views[i]});
                ui.endPanel();
                y += rowH;
            }
        }
    }
    if (!mStepError.empty()) {
        y += 0.3f * line;
        const float top = y;
        wrapped(mStepError, SpanStyle::Normal);
        dl.rect({{left - 5.0f * scale, top}, {left - 2.0f * scale, y}}, kError);
    }
    y += 0.4f * line;
    dl.rect({{left, y}, {left + width, y + std::max(1.0f, scale)}}, kRule);
    y += 0.6f * line;

    // The prose: clipped to what is left, scrolled by the wheel; a row for the "more below" marker under
    // it (never over its last line), then the key line at the bottom.
    const float keysY = area.max.y - pad - line;
    const Rect prose{{area.min.x, y}, {area.max.x, keysY - 1.3f * line}};
    const float visible = std::max(0.0f, prose.size().y);
    mScroll = std::clamp(mScroll, 0.0f, std::max(0.0f, mContentHeight - visible));
    dl.pushClip(prose);
    // The first step follows the lesson's introduction.
    float introHeight = 0.0f;
    if (mStep == 0 && !mLesson->intro.empty()) {
        introHeight = drawLessonProse(dl, mLesson->intro, {left, prose.min.y - mScroll}, width - 6.0f * scale, scale) + 0.5f * line;
        dl.rect({{left, prose.min.y - mScroll + introHeight}, {left + width, prose.min.y - mScroll + introHeight + std::max(1.0f, scale)}}, kRule);
        introHeight += 0.5f * line;
    }
    mContentHeight = introHeight + drawLessonProse(dl, s.prose, {left, prose.min.y - mScroll + introHeight}, width - 6.0f * scale, scale);
    dl.popClip();
    if (mContentHeight > visible && visible > 0.0f) {
        const float h = std::max(2.0f * line, visible * visible / mContentHeight);
        const float at = prose.min.y + (visible - h) * mScroll / std::max(1.0f, mContentHeight - visible);
        dl.rect({{area.max.x - 5.0f * scale, at}, {area.max.x - 2.0f * scale, at + h}}, kDim);
        if (mScroll + visible < mContentHeight - 1.0f)
            dl.textClipped({left, keysY - 1.15f * line}, "(more below: wheel)", kDim, area.max.x - pad);
    }
    dl.textClipped({left, keysY}, "PgUp/PgDn step   T try it   B back" +
                                      std::string(s.animation.kind != LessonAnimation::Kind::None ? "   Space play" : ""),
                   kDim, area.max.x - pad);
}

nlohmann::json LessonPlayer::sidecar(const LessonHost& host) const {
    nlohmann::json j = {{"path", mPath},
                        {"steps", mLesson ? int(mLesson->steps.size()) : 0},
                        {"step", mLesson ? mStep + 1 : 0},
                        {"try_it", mTryIt},
                        {"matches_step", mMatches},
                        {"error", !mLoadError.empty() ? mLoadError : mStepError},
                        {"panel", {mArea.min.x, mArea.min.y, mArea.max.x, mArea.max.y}},
                        {"prose_height", mContentHeight}};
    if (const LessonStep* s = step()) {
        j["step_title"] = s->title;
        if (s->animation.kind != LessonAnimation::Kind::None)
            j["animation"] = {{"what", describeAnimation(s->animation)},
                              {"playing", mPlaying},
                              {"seconds", mTime}};
    }
    const LessonWindowState now = host.lessonWindowState();
    if (!now.lights.empty()) {
        const auto v3 = [](glm::dvec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); };
        j["light"] = {{"position", v3(now.lights[0].position)}, {"direction", v3(now.lights[0].direction)}};
    }
    j["orbit_centre"] = {mOrbitCentre.x, mOrbitCentre.y, mOrbitCentre.z};
    return j;
}

}  // namespace airlight
