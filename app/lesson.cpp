#include "lesson.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

#include "cli_args.h"
#include "comparison_grid.h"
#include "core/animation_io.h"
#include "core/error.h"
#include "core/text.h"
#include "core/image_io.h"
#include "core/staged_folder.h"
#include "lesson_markdown.h"
#include "platform/context_egl.h"
#include "render_job.h"
#include "ui/font.h"
#include "view_figure.h"
#include "report/error_images.h"
#include "report/run_spread.h"
#include "report/text_output.h"
#include "scene/light_orbit.h"
#include "scene/orbit_target.h"
#include "techniques/registry.h"

namespace airlight {

using viz::InputError;

namespace {

using viz::trim;

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::string item;
    for (char c : text + ",") {
        if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
            if (!item.empty()) out.push_back(item);
            item.clear();
        } else {
            item += c;
        }
    }
    return out;
}

// "2s", "2 s", "2.5" (seconds): the duration of an animation.
double parseSeconds(const std::string& text) {
    std::string number = trim(text);
    if (!number.empty() && number.back() == 's') number = trim(number.substr(0, number.size() - 1));
    double seconds = 0.0;
    try {
        seconds = parseNumber(number, "animation duration");
    } catch (const InputError&) {
        seconds = -1.0;
    }
    if (!(seconds >= 0.1 && seconds <= 600.0))
        throw InputError("animation duration '" + text + "' must be seconds from 0.1 to 600, e.g. 2s");
    return seconds;
}

// `animate: substeps 2s` or `animate: light orbit 4s`.
LessonAnimation parseAnimation(const std::string& value, int line) {
    const std::vector<std::string> words = splitList(value);
    LessonAnimation a;
    a.line = line;
    if (words.size() == 2 && words[0] == "substeps") {
        a.kind = LessonAnimation::Kind::Substeps;
        a.seconds = parseSeconds(words[1]);
    } else if (words.size() == 3 && words[0] == "light" && words[1] == "orbit") {
        a.kind = LessonAnimation::Kind::LightOrbit;
        a.seconds = parseSeconds(words[2]);
    } else {
        throw InputError("animate takes 'substeps DURATION' or 'light orbit DURATION' (e.g. 'substeps 2s'), got '" +
                         value + "'");
    }
    return a;
}

}  // namespace

std::string describeAnimation(const LessonAnimation& animation) {
    switch (animation.kind) {
        case LessonAnimation::Kind::Substeps: return "substeps over " + viz::report::formatFigure(animation.seconds, "%g") + " s";
        case LessonAnimation::Kind::LightOrbit: return "light orbit over " + viz::report::formatFigure(animation.seconds, "%g") + " s";
        case LessonAnimation::Kind::None: break;
    }
    return {};
}

Lesson parseLesson(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError("cannot read lesson '" + path + "'");
    Lesson lesson;
    lesson.path = path;
    std::string line;
    int number = 0;
    LessonStep* step = nullptr;
    bool inBlock = false, stepHasBlock = false;
    int blockLine = 0;
    const auto fail = [&](int at, const std::string& why) {
        throw InputError(path + ":" + std::to_string(at) + ": " + why);
    };
    // The Markdown before the first step and of each step, parsed once read.
    std::string introText;
    std::vector<std::string> stepTexts;
    std::string* prose = &introText;
    std::set<std::string> blockSettings;  // names set in the current block: a second one is a mistake
    std::vector<std::pair<std::string, int>> blockSets;  // the block's `set` items and their lines
    while (std::getline(in, line)) {
        ++number;
        if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte-order mark
        const std::string t = trim(line);
        if (inBlock) {
            if (t == "```") {
                inBlock = false;
                for (const auto& [item, at] : blockSets) {
                    viz::Settings one;
                    try {
                        parseSetting(item, one, step->technique);
                    } catch (const InputError& e) {
                        fail(at, e.what());
                    }
                    for (const auto& [name, v] : one) {
                        if (!blockSettings.insert(name).second) fail(at, "'" + name + "' is set twice in this step");
                        step->settings[name] = v;
                    }
                }
                continue;
            }
            if (t.empty() || t[0] == '#') continue;
            const std::size_t colon = t.find(':');
            if (colon == std::string::npos) fail(number, "expected 'key: value', got '" + t + "'");
            const std::string key = trim(t.substr(0, colon)), value = trim(t.substr(colon + 1));
            if (value.empty()) fail(number, "'" + key + "' has no value");
            try {
                if (key == "scene") step->scene = value;
                else if (key == "technique") step->technique = value;
                else if (key == "size") {
                    const glm::ivec2 size = parseSize(value);
                    step->width = size.x, step->height = size.y;
                } else if (key == "set") {
                    // Read when the block closes, once the step's technique is known: a named value's
                    // number is that technique's (epipole=paper is 2 in vsv, 1 in ivsv).
                    for (const std::string& item : splitList(value)) blockSets.emplace_back(item, number);
                } else if (key == "animate") step->animation = parseAnimation(value, number);
                else if (key == "stage") step->stage = value;
                else if (key == "views") step->views = splitList(value);
                else if (key == "compare") step->compare = splitList(value);
                else if (key == "inspect") {
                    std::istringstream xy(value);
                    int x = -1, y = -1;
                    if (!(xy >> x >> y) || x < 0 || y < 0 || !(xy >> std::ws).eof())
                        fail(number, "inspect takes one pixel 'x y', got '" + value + "'");
                    step->inspect = glm::ivec2(x, y);
                } else {
                    fail(number, "unknown key '" + key + "' (known: scene, technique, size, set, stage, views, inspect, animate, compare)");
                }
            } catch (const InputError& e) {
                const std::string what = e.what();
                if (what.rfind(path + ":", 0) == 0) throw;
                fail(number, what);
            }
            continue;
        }
        if (t.rfind("# ", 0) == 0 && lesson.title.empty() && !step) {
            lesson.title = trim(t.substr(2));
        } else if (t.rfind("## ", 0) == 0) {
            // A new step inherits what the previous one showed.
            LessonStep next;
            if (step) {
                next.scene = step->scene, next.technique = step->technique;
                next.width = step->width, next.height = step->height;
            }
            next.title = trim(t.substr(3));
            next.line = number;
            lesson.steps.push_back(next);
            step = &lesson.steps.back();
            stepTexts.emplace_back();
            prose = &stepTexts.back();
            stepHasBlock = false;
        } else if (t == "```airlight") {
            if (!step) fail(number, "an airlight block belongs in a step (after a '## ' heading)");
            if (stepHasBlock) fail(number, "a step has one airlight block");
            step->settings.clear();  // a step's settings replace the previous step's
            blockSettings.clear();
            blockSets.clear();
            inBlock = stepHasBlock = true;
            blockLine = number;
        } else {
            *prose += line + "\n";
        }
    }
    if (inBlock) fail(blockLine, "the airlight block is not closed with ```");
    lesson.intro = parseProse(introText);
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) lesson.steps[i].prose = parseProse(stepTexts[i]);
    if (lesson.title.empty()) fail(1, "a lesson starts with a '# Title' line");
    if (lesson.steps.empty()) fail(number, "a lesson needs at least one step ('## ' heading with an airlight block)");
    const std::vector<std::string> ids = viz::techniqueIds();
    for (const LessonStep& s : lesson.steps) {
        const std::string where = "step '" + s.title + "': ";
        if (s.scene.empty()) fail(s.line, "step '" + s.title + "' has no scene (set 'scene:' in it or a step before)");
        if (s.technique.empty()) fail(s.line, "step '" + s.title + "' has no technique");
        if (std::find(ids.begin(), ids.end(), s.technique) == ids.end()) {
            std::string known;
            for (const std::string& id : ids) known += (known.empty() ? "" : ", ") + id;
            fail(s.line, where + "unknown technique '" + s.technique + "' (known: " + known + ")");
        }
        for (const std::string& id : s.compare)
            if (std::find(ids.begin(), ids.end(), id) == ids.end() || id == "reference")
                fail(s.line, where + "compare: '" + id + "' is not a technique to compare with the reference");
        // The comparison grid takes the right-hand side of the window, where its tiles show the step's L_air:
        // a view it would hide is refused here rather than left unseen.
        if (!s.compare.empty())
            for (const std::string& v : s.views)
                if (v != "final" && v != "airlight")
                    fail(s.line, where + "compare: shows L_air beside the final frame; the view '" + v +
                                     "' would be hidden behind the comparison (use final and airlight)");
        // What the window and the export would reject later is reported here, at the step.
        const std::unique_ptr<viz::Technique> technique = viz::makeTechnique(s.technique);
        try {
            (void)viz::completeSettings(*technique, s.settings);
        } catch (const InputError& e) {
            fail(s.line, where + e.what());
        }
        const auto& stages = technique->stages();
        const viz::StageInfo* stage = stages.empty() ? nullptr : &stages.back();
        if (!s.stage.empty()) {
            stage = nullptr;
            std::string known;
            for (const viz::StageInfo& st : stages) {
                if (st.id == s.stage) stage = &st;
                known += (known.empty() ? "" : ", ") + st.id;
            }
            if (!stage) fail(s.line, where + s.technique + " has no stage '" + s.stage + "' (its stages: " + known + ")");
        }
        if (s.animation.kind == LessonAnimation::Kind::Substeps && (!stage || stage->substepParam.empty())) {
            std::string with;
            for (const viz::StageInfo& st : stages)
                if (!st.substepParam.empty()) with += (with.empty() ? "" : ", ") + st.id;
            fail(s.animation.line, "stage '" + (stage ? stage->id : std::string("?")) + "' of " + s.technique +
                                       " has no sub-steps to animate (" +
                                       (with.empty() ? std::string("none of its stages has any") : "stages with sub-steps: " + with) + ")");
        }
        if (s.animation.kind == LessonAnimation::Kind::LightOrbit && !technique->needsGl())
            fail(s.animation.line, s.technique + " renders on the CPU in seconds per frame: animate the light with a GPU technique");
    }
    return lesson;
}

std::string lessonDirectory() {
    if (const char* env = std::getenv("AIRLIGHT_LESSON_DIR"); env != nullptr && env[0] != '\0') {
        return env;
    }
    return std::string(VIZ_SOURCE_DIR) + "/lessons";
}

std::string matchLesson(const std::string& name, const std::vector<std::string>& lessons,
                        std::vector<std::string>& matches) {
    matches.clear();
    if (name.empty()) return "";
    const auto pick = [&](const auto& accepts) {
        for (const std::string& l : lessons)
            if (accepts(l)) matches.push_back(l);
        return matches.size() == 1 ? matches.front() : std::string();
    };
    const auto lower = [](std::string s) {
        for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    const std::string want = lower(name);
    for (const std::string& l : lessons)
        if (lower(l) == want) return l;
    // A number: the lesson whose name starts with that number ("3" and "03" are 03-slices).
    if (std::all_of(want.begin(), want.end(), [](unsigned char c) { return std::isdigit(c); })) {
        const unsigned long long n = want.size() <= 9 ? std::stoull(want) : ~0ull;
        return pick([&](const std::string& l) {
            std::size_t digits = 0;
            while (digits < l.size() && std::isdigit(static_cast<unsigned char>(l[digits]))) ++digits;
            return digits > 0 && digits <= 9 && std::stoull(l.substr(0, digits)) == n;
        });
    }
    // The start of a name, else any part of it (after the number: "slices" is 03-slices).
    if (std::string one = pick([&](const std::string& l) { return lower(l).rfind(want, 0) == 0; }); !one.empty() ||
        !matches.empty())
        return one;
    return pick([&](const std::string& l) { return lower(l).find(want) != std::string::npos; });
}

std::string findLesson(const std::string& nameOrPath) {
    namespace fs = std::filesystem;
    if (nameOrPath.size() > 3 && nameOrPath.substr(nameOrPath.size() - 3) == ".md") return nameOrPath;
    std::string problem;  // the first folder's, when no folder has the lesson
    for (const fs::path& dir : {fs::path(lessonDirectory()), fs::path("lessons")}) {
        // The lessons of a folder, in order; its README describes the format and is not one.
        std::vector<std::string> lessons;
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(dir, ec))
            if (entry.path().extension() == ".md" && entry.path().filename() != "README.md")
                lessons.push_back(entry.path().stem().string());
        if (lessons.empty()) continue;
        std::sort(lessons.begin(), lessons.end());
        std::vector<std::string> matches;
        if (const std::string found = matchLesson(nameOrPath, lessons, matches); !found.empty())
            return (dir / (found + ".md")).string();
        const auto list = [](const std::vector<std::string>& names) {
            std::string out;
            for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
            return out;
        };
        if (problem.empty())
            problem = matches.size() > 1 ? "lesson '" + nameOrPath + "' could be any of " + list(matches) + ": name one"
                                         : "unknown lesson '" + nameOrPath + "' (known: " + list(lessons) + ")";
    }
    if (problem.empty())
        problem = "unknown lesson '" + nameOrPath + "': no lessons in '" + lessonDirectory() + "' or './lessons'";
    throw InputError(problem);
}

namespace {

// A step's `compare:` measured now, on the machine writing the handout: each technique's time (median
// of three runs after a warm-up, the stages' glFinish + steady clock) and the relative L2 error of its
// L_air against the reference's, as an HTML table with the machine it was measured on.
// The figure the window draws for `view` of the job's last run (view_figure.h) at `exposure` stops, and
// the view's label. Throws InputError when the run has no such view.
Figure viewFigure(const RenderJob& job, const std::string& view, float exposure, const viz::ui::FontAtlas& font,
                  std::string& label) {
    const viz::Intermediate* in = view == "final" || view == "airlight" ? nullptr : job.findIntermediate(view);
    ViewState shown;
    if (in) {
        makePane(shown.pane, *in, 0);
    } else {
        shown.pane.id = view;
        shown.pane.label = view == "final" ? "Final image" : "Airlight L_air";
        shown.pane.units = "radiance";
        shown.pane.kind = viz::ViewKind::Colour;
        shown.pane.mode = DisplayMode::HdrColour;
        uploadImage(shown.pane, job.layerImage(view));
    }
    label = in ? in->label : shown.pane.label;
    shown.display.channel = defaultChannel(shown.pane);
    return renderFigure(shown, exposure, font);
}

// A step's animation as the handout's animated GIF: the window's animation (lesson_player.cpp) rendered
// frame by frame (a light orbit: 12 frames per second of it; sub-steps: each sub-step once, at most 48
// evenly spread, the last always), each frame the step's first view drawn as the still figures are
// (viewFigure, at their exposure), through core/animation_io.h, by the job that rendered the still
// figures (its light and sub-step are moved frame by frame; the last frame is the still state). Returns
// the figure's HTML, or a note where this build cannot write a GIF.
std::string animationFigure(const LessonStep& s, RenderJob& job, std::size_t k, float exposure,
                            const viz::ui::FontAtlas& font, viz::StagedFolder& staged) {
    const std::string view = s.views.empty() ? "final" : s.views.front();
    std::vector<double> substeps;  // the values of the stage's sub-step parameter, in order
    std::string substepParam;
    int frames = 0, fps = 12;
    if (s.animation.kind == LessonAnimation::Kind::Substeps) {
        const int stage = stageIndex(job.technique(), s.stage);
        substepParam = job.technique().stages()[std::size_t(stage)].substepParam;
        std::vector<double> all = job.technique().substepValues(stage, viz::completeSettings(job.technique(), s.settings));
        // The still state's run knows the stage's own count where it is fewer (minmax's walk: its nodes).
        const auto counted = job.lastOutput().substepCounts.find(stage);
        if (counted != job.lastOutput().substepCounts.end() && counted->second < int(all.size())) {
            const double whole = all.back();
            all.resize(std::size_t(std::max(counted->second, 1)));
            all.back() = whole;
        }
        const int count = int(all.size());
        frames = std::min(count, 48);
        for (int i = 0; i < frames; ++i)
            substeps.push_back(all[std::size_t(frames == count ? i : (i + 1) * count / frames - 1)]);
        fps = std::clamp(int(std::lround(double(frames) / s.animation.seconds)), 1, viz::kMaxFramesPerSecond);
    } else {
        frames = std::clamp(int(std::lround(s.animation.seconds * fps)), 2, 120);
    }
    const viz::scene::Light light = job.scene().lights.empty() ? viz::scene::Light{} : job.scene().lights.front();
    const glm::dvec3 centre = viz::scene::orbitTarget(job.scene());
    const std::string file = "step" + std::to_string(k + 1) + "-animation.gif";
    std::string label;
    glm::ivec2 size{0};
    try {
        std::unique_ptr<viz::AnimationWriter> writer;
        for (int i = 0; i < frames; ++i) {
            if (!substeps.empty()) job.setSetting(substepParam, substeps[std::size_t(i)]);
            else job.scene().lights.front() = viz::scene::orbitLight(light, centre, double(i + 1) / double(frames));
            job.setFrame(i);
            (void)job.run();
            const Figure figure = viewFigure(job, view, exposure, font, label);
            if (figure.image.empty()) throw InputError("frame " + std::to_string(i) + " has nothing to show: " + figure.caption);
            if (!writer) {
                size = {figure.image.width, figure.image.height};
                writer = std::make_unique<viz::AnimationWriter>(staged.path(file),
                                                                viz::AnimationSpec{size.x, size.y, frames, fps, false});
            }
            // The figure is already what the display shows (linear, encoded as a PNG is): exposure 1.
            writer->add(figure.image, 1.0f);
        }
        writer->commit();
    } catch (const viz::InputError& e) {
        // The portable build has no GIF encoder: the page says so rather than failing the export.
        return "<p class=\"state\">The animation (" + viz::report::escapeHtml(describeAnimation(s.animation)) +
               ") is not in this handout: " + viz::report::escapeHtml(e.what()) + ".</p>\n";
    }
    return "<figure><img src=\"" + file + "\" alt=\"animation of " + viz::report::escapeHtml(view) + "\" width=\"" +
           std::to_string(size.x) + "\" height=\"" + std::to_string(size.y) + "\" class=\"animation\" data-frames=\"" +
           std::to_string(frames) + "\"><figcaption>" + viz::report::escapeHtml(label) + ", animated: " +
           viz::report::escapeHtml(describeAnimation(s.animation)) + "<br><span class=\"range\">" + std::to_string(frames) +
           " frames at " + std::to_string(fps) + " per second, at the still figure's exposure and range</span>"
           "</figcaption></figure>\n";
}

std::string liveComparison(const LessonStep& s, glm::ivec2 size) {
    const auto request = [&](const std::string& technique) {
        RenderRequest r;
        r.scene = s.scene;
        r.technique = technique;
        r.width = size.x;
        r.height = size.y;
        if (technique == s.technique) r.settings = s.settings;
        return r;
    };
    viz::Image reference;
    {
        RenderJob job(request("reference"));
        reference = job.run().airlight;
    }
    std::string rows, renderer = "CPU only", clock;
    double baseline = 0.0;
    bool noisy = false;
    for (const std::string& id : s.compare) {
        RenderJob job(request(id));
        (void)job.run();  // warm-up: shaders, allocations
        std::vector<double> times;
        viz::Image airlight;
        for (int run = 0; run < 3; ++run) {
            const viz::FrameOutput& out = job.run();
            times.push_back(out.timing.totalMilliseconds());
            clock = out.timing.clock;
            if (run == 2) airlight = out.airlight;
        }
        if (job.technique().needsGl()) {
            if (const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER))) renderer = name;
        }
        std::sort(times.begin(), times.end());
        const double ms = times[1];
        if (id == s.compare.front()) baseline = ms;
        // A time whose runs lie far apart is marked, as the report marks it (report/run_spread.h).
        char cells[160];
        std::snprintf(cells, sizeof cells, "<td>%s</td><td>%.2f</td>",
                      tileErrorText(viz::report::compareImages(airlight, reference)).c_str(), ms / std::max(baseline, 1e-9));
        rows += "<tr><td>" + viz::report::escapeHtml(id) + "</td>" +
                viz::report::timeCellHtml(viz::format("%.1f", ms), ms, viz::report::spreadOf(times), noisy) + cells + "</tr>\n";
    }
    return "<table class=\"compare\"><tr><th>technique</th><th>time (ms, median of 3)</th><th>L_air against the "
           "reference</th><th>time / " + viz::report::escapeHtml(s.compare.front()) + "</th></tr>\n" + rows +
           "</table>\n<p class=\"state\">Measured when this page was written, at " + std::to_string(size.x) + "x" +
           std::to_string(size.y) + " on " + viz::report::escapeHtml(renderer) + " (" + viz::report::escapeHtml(clock) +
           "). Another machine gives other figures: in the window this step times them live (the comparison grid).</p>\n" +
           (noisy ? viz::report::noisyFootnoteHtml("Compare such a time live in the window.") : std::string());
}

}  // namespace

void exportLesson(const Lesson& lesson, const std::string& folder, glm::ivec2 size) {
    namespace fs = std::filesystem;
    if (folder.empty()) throw InputError("lesson --export needs a folder");
    viz::StagedFolder staged(folder);
    const viz::ui::FontAtlas font = viz::ui::FontAtlas::bake(viz::ui::FontAtlas::defaultFontPath(), 15.0f);
    std::unique_ptr<viz::HeadlessContext> figureContext;  // for the figures of CPU techniques' steps
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
                       viz::report::escapeHtml(lesson.title) +
                       "</title><style>body{font-family:DejaVu Sans,sans-serif;max-width:60em;margin:2em;color:#222}"
                       "figure{display:inline-block;margin:0.3em;text-align:center;max-width:100%}img{image-rendering:pixelated;"
                       "border:1px solid #ccc;max-width:100%;height:auto}code{background:#f2f2f2}.state{color:#555;font-size:0.85em}"
                       ".range{color:#555;font-size:0.8em}table.compare{border-collapse:collapse}"
                       "table.compare td,table.compare th{border:1px solid #ccc;padding:0.2em 0.6em;text-align:right}</style>"
                       "</head><body>\n<h1>" + viz::report::escapeHtml(lesson.title) + "</h1>\n" +
                       proseHtml(lesson.intro);
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        const LessonStep& s = lesson.steps[k];
        RenderRequest request;
        request.scene = s.scene;
        request.technique = s.technique;
        request.width = size.x > 0 ? size.x : s.width;
        request.height = size.y > 0 ? size.y : s.height;
        request.settings = s.settings;
        request.stopAfter = s.stage;
        request.views = s.views;
        RenderJob job(request);
        const viz::FrameOutput& out = job.run();
        for (const std::string& line : job.badPixelWarnings()) {
            std::fprintf(stderr, "airlight: warning: %s:%d: step '%s': %s\n", lesson.path.c_str(), s.line, s.title.c_str(),
                         line.c_str());
        }
        html += "<h2>" + viz::report::escapeHtml(s.title) + "</h2>\n" + proseHtml(s.prose);
        std::string state = s.technique + " on " + s.scene;
        if (!s.stage.empty()) state += ", stopped after " + s.stage;
        const std::vector<viz::ParamInfo> params = viz::makeTechnique(s.technique)->params();
        for (const auto& [name, value] : s.settings) state += ", " + viz::settingText(params, name, value);
        // Both animations end on the static step's state (every sub-step; the light back where it was):
        // the image is the animation's last frame.
        if (s.animation.kind != LessonAnimation::Kind::None)
            state += "; animated: " + describeAnimation(s.animation) + " (the still figures show its last frame; the "
                     "animated GIF below plays it)";
        html += "<p class=\"state\">" + viz::report::escapeHtml(state) + "</p>\n";
        const std::vector<std::string> views = s.views.empty() ? std::vector<std::string>{"final", "airlight"} : s.views;
        // The window's exposure for this frame: the final image's automatic exposure in stops (L_air's
        // while a stopped run has no final image yet), rounded to the window's half stops.
        const viz::Image& exposed = out.final.empty() ? out.airlight : out.final;
        const float exposure =
            exposed.empty() ? 0.0f : std::round(std::log2(std::max(autoExposure(exposed), 1e-30f)) / 0.5f) * 0.5f;
        // Figures are drawn through the window's own shaders: a CPU technique's step needs a context too.
        if (!job.technique().needsGl()) {
            if (!figureContext) figureContext = viz::HeadlessContext::create(false);
            figureContext->makeCurrent();
        }
        for (const std::string& view : views) {
            std::string label;
            Figure figure;
            try {
                figure = viewFigure(job, view, exposure, font, label);
            } catch (const InputError& e) {
                throw InputError(lesson.path + ":" + std::to_string(s.line) + ": step '" + s.title + "': " + e.what());
            }
            if (figure.image.empty()) {
                throw InputError(lesson.path + ":" + std::to_string(s.line) + ": step '" + s.title + "': view '" + view +
                                 "' has nothing to show: " + figure.caption);
            }
            std::string file = "step" + std::to_string(k + 1) + "-";
            for (char c : view) file += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
            file += ".png";
            viz::writeImage(figure.image, staged.path(file));
            // A plot says what it drew (plots and curves), an image its scale (screen pixels per texel).
            const std::string what = figure.plots > 0
                                         ? " class=\"plot\" data-plots=\"" + std::to_string(figure.plots) + "\" data-series=\"" +
                                               std::to_string(figure.series) + "\""
                                         : " data-texel-scale=\"" + std::to_string(figure.texelScale) + "\"";
            html += "<figure><img src=\"" + file + "\" alt=\"" + viz::report::escapeHtml(view) + "\" width=\"" +
                    std::to_string(figure.image.width) + "\" height=\"" + std::to_string(figure.image.height) + "\"" + what +
                    "><figcaption>" + viz::report::escapeHtml(label) +
                    "<br><span class=\"range\">" + viz::report::escapeHtml(figure.caption) + "</span></figcaption></figure>\n";
        }
        if (s.animation.kind != LessonAnimation::Kind::None)
            html += animationFigure(s, job, k, exposure, font, staged);
        if (!s.compare.empty()) html += liveComparison(s, {request.width, request.height});
    }
    html += "</body></html>\n";
    viz::report::writeTextFile(staged.path("index.html"), html);
    staged.commit();
}

}  // namespace airlight
