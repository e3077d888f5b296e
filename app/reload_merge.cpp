#include "reload_merge.h"

namespace airlight {

SceneLighting lightingOf(const viz::scene::Scene& scene) { return {scene.medium, scene.lights}; }

namespace {

bool sameLights(const std::vector<viz::scene::Light>& a, const std::vector<viz::scene::Light>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].type != b[i].type || a[i].name != b[i].name) return false;
    return true;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
}

}  // namespace

ReloadMerge keepUserEdits(const SceneLighting& base, const viz::scene::Scene& mine, viz::scene::Scene& theirs) {
    ReloadMerge merge;
    std::vector<std::string> kept, replaced;
    // One value: the user's edit survives unless the file changed it too.
    auto field = [&](const auto& baseValue, const auto& mineValue, auto& theirsValue, const std::string& name) {
        if (mineValue == baseValue) return;  // not edited: the file's value, changed or not
        if (theirsValue == baseValue) {
            theirsValue = mineValue;
            kept.push_back(name);
        } else {
            replaced.push_back(name);
        }
    };
    field(base.medium.sigma_s, mine.medium.sigma_s, theirs.medium.sigma_s, "medium sigma_s");
    field(base.medium.sigma_a, mine.medium.sigma_a, theirs.medium.sigma_a, "medium sigma_a");
    field(base.medium.g, mine.medium.g, theirs.medium.g, "medium g");
    // The window's lights are the base's lights, edited (the window adds and removes none).
    std::vector<std::string> lost;
    if (sameLights(base.lights, mine.lights)) {
        merge.lightsRematched = sameLights(base.lights, theirs.lights);
        for (std::size_t i = 0; i < base.lights.size(); ++i) {
            const viz::scene::Light& b = base.lights[i];
            const viz::scene::Light& m = mine.lights[i];
            const std::string name = "light " + std::to_string(i + 1);
            if (!merge.lightsRematched) {
                if (m.position != b.position || m.direction != b.direction || m.intensity != b.intensity) lost.push_back(name);
                continue;
            }
            viz::scene::Light& t = theirs.lights[i];
            field(b.position, m.position, t.position, name + " position");
            field(b.direction, m.direction, t.direction, name + " direction");
            field(b.intensity, m.intensity, t.intensity, name + " intensity");
        }
    }
    merge.kept = int(kept.size());
    merge.replaced = int(replaced.size());
    if (!kept.empty()) merge.summary += "; kept your edits (" + joined(kept) + ")";
    if (!replaced.empty()) merge.summary += "; the file changed " + joined(replaced) + " too, and its value is taken";
    if (!lost.empty())
        merge.summary += "; the file's lights changed, so your edits of " + joined(lost) + " are not carried over";
    return merge;
}

}  // namespace airlight
