#include "scene/stiff_scenes.h"

#include <cmath>

#include "scene/builtin_scenes.h"
#include "scene/scene_building.h"
#include "scene/validate.h"

namespace viz::scene {

namespace {


// Multiplies every length by s and keeps every image the same: extinction scales by 1/s and intensities
// of point and spot lights by s^2 (so E = I / r^2 is unchanged), directional irradiance stays.
void scaleScene(Scene& scene, double s) {
    for (Mesh& m : scene.meshes)
        for (glm::vec3& p : m.positions) p = glm::vec3(glm::dvec3(p) * s);
    for (Light& l : scene.lights) {
        l.position *= s;
        l.halfU *= s;
        l.halfV *= s;
        if (l.type == LightType::Point || l.type == LightType::Spot) l.intensity *= s * s;
    }
    scene.camera.position *= s;
    scene.camera.znear *= s;
    scene.camera.zfar *= s;
    scene.medium.sigma_s /= s;
    scene.medium.sigma_a /= s;
}

// Replaces the scene's lights by one point light.
void pointLightAt(Scene& scene, glm::dvec3 position, double intensity) {
    Light l;
    l.name = "point";
    l.type = LightType::Point;
    l.position = position;
    l.intensity = intensity;
    l.colour = {1.0, 0.95, 0.9};
    scene.lights = {l};
}

int addMaterial(Scene& scene, const std::string& name, glm::vec3 albedo) {
    Material m;
    m.name = name;
    m.baseColorFactor = glm::vec4(albedo, 1.0f);
    scene.materials.push_back(m);
    return int(scene.materials.size()) - 1;
}

std::vector<StiffCase> makeCases() {
    std::vector<StiffCase> cases;
    auto add = [&](std::string id, std::string cls, std::string what, std::string base,
                   std::function<void(Scene&)> edit, double exclude = 0.0) {
        StiffCase c;
        c.id = std::move(id);
        c.caseClass = std::move(cls);
        c.description = std::move(what);
        c.baseScene = std::move(base);
        c.edit = std::move(edit);
        c.excludeAroundLight = exclude;
        cases.push_back(std::move(c));
    };

    // ---- medium: extinction from 1e-6 to 50 per scene unit ----
    add("extinction-1e-6", "medium", "sigma_s = sigma_a = 5e-7: L_air ~ 1e-6 of the default, linear in sigma_s", "grate",
        [](Scene& s) { s.medium.sigma_s = s.medium.sigma_a = 5e-7; });
    add("extinction-50", "medium",
        "sigma_t = 50 (sigma_s = 25): the camera inside the spot cone 0.5 below the light, everything beyond "
        "0.2 units is extinguished (e^-10)",
        "grate", [](Scene& s) {
            s.medium.sigma_s = s.medium.sigma_a = 25.0;
            s.camera = lookAt("near-light", {0.0, 5.5, 0.15}, {0.3, 4.0, -1.0}, 1.2, 0.01, 40.0);
        });

    // ---- intensity from 1e-3 to 1e7 ----
    add("intensity-1e-3", "intensity", "spot intensity 1e-3 cd (4e5 times dimmer than grate's)", "grate",
        [](Scene& s) { s.lights[0].intensity = 1e-3; });
    add("intensity-1e7", "intensity", "spot intensity 1e7 cd: values far above 1 (float headroom, no clamping)", "grate",
        [](Scene& s) { s.lights[0].intensity = 1e7; });

    // ---- scene scale from 1e-3 to 1e4 units, same image ----
    add("scale-1e-3", "scale", "grate scaled by 1e-3 (sigma x 1e3, I x 1e-6): the same image", "grate",
        [](Scene& s) { scaleScene(s, 1e-3); });
    add("scale-1e4", "scale", "grate scaled by 1e4 (sigma x 1e-4, I x 1e8): the same image, world coordinates ~1e4",
        "grate", [](Scene& s) { scaleScene(s, 1e4); });

    // ---- rays through or near the light ----
    add("ray-through-light", "singular-ray",
        "a point light exactly on the centre pixel's ray (h = 0; the pixel itself is left out of the figures)",
        "grate", [](Scene& s) {
            pointLightAt(s, {0.0, 4.5, 0.0}, 60.0);
            s.camera = lookAt("at-light", {0.0, 4.5, 7.0}, {0.0, 4.5, 0.0}, 0.9, 0.05, 40.0);
        }, 1.5);
    add("ray-near-light", "near-light",
        "a point light 1e-6 off the centre pixel's ray (that pixel counts: ~3e5 times brighter than the rest)",
        "grate", [](Scene& s) {
            pointLightAt(s, {1e-6, 4.5, 0.0}, 60.0);
            s.camera = lookAt("at-light", {0.0, 4.5, 7.0}, {0.0, 4.5, 0.0}, 0.9, 0.05, 40.0);
        });

    // ---- where the light projects: epipole cases ----
    add("light-behind-camera", "epipole", "the spot sits 1.5 behind the camera and shines past it into the scene",
        "grate", [](Scene& s) {
            s.camera = lookAt("ahead", {0.0, 2.5, 6.0}, {0.0, 1.0, 0.0}, 0.9, 0.05, 40.0);
            s.lights[0].position = {0.0, 3.0, 7.5};
            s.lights[0].direction = glm::normalize(glm::dvec3(0.0, 0.5, 0.0) - s.lights[0].position);
        });
    add("epipole-at-pixel-centre", "epipole", "the camera looks straight at the spot: its position projects onto a pixel centre",
        "grate", [](Scene& s) {
            s.camera = lookAt("at-spot", {0.0, 2.0, 6.5}, s.lights[0].position, 0.9, 0.05, 40.0);
        });
    // The colonnade's sun enters through the windows; a window centre is at (-4, 3.1, -6.2).
    add("sun-along-view", "epipole",
        "the camera stands in a shaft just inside a window and looks exactly along the sun's travel "
        "(the anti-solar epipole at the image centre)",
        "colonnade", [](Scene& s) {
            const glm::dvec3 travel = s.lights[0].direction, window{-4.0, 3.1, -6.2};
            s.camera = lookAt("along-sun", window + 1.0 * travel, window + 2.0 * travel, 0.95, 0.05, 50.0);
        });
    add("sun-against-view", "epipole",
        "the camera looks straight back at the sun through a window (the solar epipole at the image centre)",
        "colonnade", [](Scene& s) {
            const glm::dvec3 travel = s.lights[0].direction, window{-4.0, 3.1, -6.2};
            s.camera = lookAt("into-sun", window + 6.0 * travel, window, 0.95, 0.05, 50.0);
        });
    add("grazing-sun", "epipole", "the sun 1 degree above the horizon, grazing through the windows", "colonnade",
        [](Scene& s) {
            const double e = 1.0 * 3.14159265358979323846 / 180.0;
            s.lights[0].direction = glm::normalize(glm::dvec3(0.3 * std::cos(e), -std::sin(e), std::cos(e)));
        });

    // ---- light through thin walls ----
    add("sun-grazing-ceiling", "leak",
        "a low sun (2 degrees up) travelling along the hall, parallel to its window wall: no light enters, and "
        "the sun grazes the one-sided ceiling above the dark interior (lit air only outside the windows)",
        "colonnade", [](Scene& s) {
            const double e = 2.0 * 3.14159265358979323846 / 180.0;
            s.lights[0].direction = glm::dvec3(-std::cos(e), -std::sin(e), 0.0);
            // colonnade's roof is a slab; this case is about a one-sided ceiling: one quad, facing down.
            for (Mesh& m : s.meshes) {
                if (m.name != "roof") continue;
                MeshBuilder ceiling("roof", m.material);
                ceiling.quad({-10, 6, -6.4}, {10, 6, -6.4}, {10, 6, 6}, {-10, 6, 6});
                m = ceiling.take();
            }
        });

    // ---- where the camera is ----
    add("camera-in-lit-volume", "camera-placement", "the camera inside the spot's cone under the grate, looking across it",
        "grate", [](Scene& s) {
            s.camera = lookAt("inside", {0.1, 1.5, 0.2}, {-3.0, 1.0, -2.0}, 1.0, 0.05, 40.0);
        });
    add("camera-in-occluder", "camera-placement", "the camera inside a closed box in the light: every ray ends on its inside",
        "grate", [](Scene& s) {
            MeshBuilder box("enclosure", addMaterial(s, "enclosure", {0.5f, 0.5f, 0.5f}));
            box.box({0.0, 1.0, 0.0}, {0.4, 0.4, 0.4});
            s.meshes.push_back(box.take());
            s.camera = lookAt("boxed", {0.0, 1.0, 0.0}, {0.0, 1.0, -1.0}, 0.9, 0.05, 40.0);
        });

    // ---- geometry ----
    add("occluder-touching-light", "geometry",
        "a thin plate hanging beside the spot, one face through the light's position: it blocks the half of the "
        "cone on its side, starting at distance 0 from the light",
        "grate", [](Scene& s) {
            MeshBuilder plate("plate", addMaterial(s, "plate", {0.4f, 0.4f, 0.4f}));
            plate.box(s.lights[0].position + glm::dvec3(0.02, -0.25, 0.0), {0.02, 0.25, 0.4});
            s.meshes.push_back(plate.take());
        });
    add("degenerate-triangles", "geometry",
        "zero-area triangles (repeated and collinear vertices) and 1e-5-wide slivers in the light cone", "grate",
        [](Scene& s) {
            MeshBuilder junk("degenerate", addMaterial(s, "junk", {0.5f, 0.5f, 0.5f}));
            for (int i = 0; i < 8; ++i) {
                const double x = -1.0 + 0.25 * i;
                junk.triangle({x, 2.0, 0.0}, {x, 2.0, 0.0}, {x, 2.0, 0.0});            // a point
                junk.triangle({x, 1.5, -1.0}, {x, 1.5, 0.0}, {x, 1.5, 1.0});           // collinear
                junk.triangle({x, 1.0, -1.5}, {x + 1e-5, 1.0, -1.5}, {x, 1.0, 1.5});   // sliver
                junk.triangle({x, 0.5, -1.5}, {x, 2.5, -1.5}, {x + 1e-5, 0.5, -1.5});  // standing sliver
            }
            s.meshes.push_back(junk.take());
        });

    // ---- a shadow map that must cover a huge depth range ----
    add("depth-range-1e6", "depth-range", "a ground plane 1e6 across under the colonnade: the sun's map spans 1e6",
        "colonnade", [](Scene& s) {
            MeshBuilder ground("ground", addMaterial(s, "ground", {0.3f, 0.3f, 0.3f}));
            const double r = 5e5;
            ground.quad({-r, -0.01, r}, {r, -0.01, r}, {r, -0.01, -r}, {-r, -0.01, -r});
            s.meshes.push_back(ground.take());
        });

    // ---- phase function ----
    add("hg-0.99", "phase", "Henyey-Greenstein g = 0.99: a needle-sharp forward lobe", "colonnade",
        [](Scene& s) { s.medium.g = 0.99; });
    add("hg-minus-0.99", "phase", "Henyey-Greenstein g = -0.99: a needle-sharp back-scattering lobe", "grate",
        [](Scene& s) { s.medium.g = -0.99; });
    return cases;
}

}  // namespace

const std::vector<StiffCase>& stiffCases() {
    static const std::vector<StiffCase> kCases = makeCases();
    return kCases;
}

Scene buildStiffScene(const StiffCase& c) {
    Scene s = makeBuiltinScene(c.baseScene);
    c.edit(s);
    s.name = "stiff/" + c.id;
    validateScene(s);
    return s;
}

const StiffCase* findStiffCase(const std::string& id) {
    for (const StiffCase& c : stiffCases())
        if (c.id == id) return &c;
    return nullptr;
}

}  // namespace viz::scene
