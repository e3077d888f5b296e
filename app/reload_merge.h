// What a reload of the scene file keeps of the user's edits. The window edits the medium and each light's
// position, direction and intensity (panel, gizmo, a loaded session); when the file changes on disk, the
// values are merged three ways between the file as it was loaded (base), the window's scene (mine) and the
// file as it is now (theirs): a value the file changed since it was loaded is the file's (the author's
// latest word); a value the file left alone keeps the user's edit. Lights are matched by their place in
// the file's list, and only while the file keeps as many lights of the same types and names; otherwise
// every light is the file's and the merge says so.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace airlight {

// The values the window lets the user edit, as a scene file gave them.
struct SceneLighting {
    viz::scene::Medium medium;
    std::vector<viz::scene::Light> lights;
};
SceneLighting lightingOf(const viz::scene::Scene& scene);

struct ReloadMerge {
    int kept = 0;      // user edits carried into the reloaded scene
    int replaced = 0;  // user edits of values the file also changed: the file's value is taken
    bool lightsRematched = true;  // false: the file's lights changed in number, type or name; the user's light edits are gone
    // "; kept your edits (medium sigma_s, light 2 position)" and what was replaced or dropped, or "".
    std::string summary;
};

// Merges the user's edits (mine against base) into `theirs`, the scene just loaded from the file.
ReloadMerge keepUserEdits(const SceneLighting& base, const viz::scene::Scene& mine, viz::scene::Scene& theirs);

}  // namespace airlight
