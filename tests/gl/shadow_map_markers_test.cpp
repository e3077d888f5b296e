// Linked-cursor marks in shadow maps (render/shadow_map_markers.h) as the GPU techniques return them:
// the eye ray's projection, checked against the light's own matrix (GpuLights) applied here, and its
// lit/shadow changes, checked against the reference's exact lit intervals for the same ray.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "render/gpu_lights.h"
#include "render/shadow_maps.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "technique_test_util.h"
#include "techniques/reference/ray_probe.h"
#include "techniques/reference/ray_tracer.h"

namespace {

using viz::ViewMarker;
using viz::render::GpuLightCpu;

constexpr int kWidth = 80, kHeight = 60;
constexpr int kMapSize = 256;

// The frame pixel whose centre ray is closest to world point p (projected by the camera's matrices).
glm::ivec2 pixelOf(const viz::scene::Camera& cam, const glm::dvec3& p) {
    const glm::dvec4 clip = viz::scene::projectionMatrix(cam, kWidth, kHeight) * viz::scene::viewMatrix(cam) *
                            glm::dvec4(p, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {int(std::floor((ndc.x * 0.5 + 0.5) * kWidth)), int(std::floor((0.5 - 0.5 * ndc.y) * kHeight))};
}

// Eye-relative point -> data uv of a 2D map by the light's shadow matrix (v = 0 at GL row 0), and whether it
// is inside the map's frustum.
glm::dvec2 mapUv2D(const GpuLightCpu& light, const glm::dvec3& p, bool* inside = nullptr) {
    const glm::dvec4 clip = glm::dmat4(light.shadowMatrix) * glm::dvec4(p, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    if (inside) *inside = clip.w > 0.0 && std::abs(ndc.x) <= 1.0 && std::abs(ndc.y) <= 1.0 && std::abs(ndc.z) <= 1.0;
    return glm::dvec2(ndc) * 0.5 + 0.5;
}

// Cube face and data uv of direction d from a point light, by the major-axis rule and face basis of
// shaders/common/shadow_map.glsl (written out here, not the function under test).
glm::dvec2 cubeUv(const glm::dvec3& d, int& face) {
    const glm::dvec3 a = glm::abs(d);
    const int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
    face = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    const double s = (face & 1) == 0 ? 1.0 : -1.0;
    glm::dvec3 forward(0.0);
    forward[axis] = s;
    const glm::dvec3 up = axis == 1 ? glm::dvec3(0.0, 0.0, s) : glm::dvec3(0.0, -1.0, 0.0);
    const glm::dvec3 right = glm::cross(forward, up);
    const glm::dvec3 trueUp = glm::cross(right, forward);
    const glm::dvec2 ndc = glm::dvec2(glm::dot(right, d), glm::dot(trueUp, d)) / glm::dot(forward, d);
    return ndc * 0.5 + 0.5;
}

struct Transition {
    double t;
    bool entersShadow;
};

// The reference's lit/shadow changes strictly inside (0, d) for scene light `light`.
std::vector<Transition> referenceTransitions(const viz::reference::RayProbe& probe, int light) {
    std::vector<Transition> out;
    const double eps = 1e-6 * probe.d;
    for (const auto& iv : probe.lights[std::size_t(light)].lit) {
        if (iv.a > eps) out.push_back({iv.a, false});
        if (iv.b < probe.d - eps) out.push_back({iv.b, true});
    }
    std::sort(out.begin(), out.end(), [](const Transition& a, const Transition& b) { return a.t < b.t; });
    return out;
}

std::vector<const ViewMarker*> points(const std::vector<ViewMarker>& marks) {
    std::vector<const ViewMarker*> out;
    for (const ViewMarker& m : marks)
        if (m.from == m.to) out.push_back(&m);
    return out;
}

bool labelSaysEnters(const ViewMarker& m) { return m.label.rfind("enters shadow", 0) == 0; }

// The light's map seen from the test: which points of space a texel of a face stands for (the light's
// own matrix from GpuLights, or the cube basis of shadow_map.glsl) and the reference's visibility there.
struct MapModel {
    const viz::scene::Scene* scene = nullptr;
    GpuLightCpu light{};
    int size = 0;

    bool cube() const { return light.info.x == viz::render::hd::kLightPoint; }
    bool directional() const { return light.info.x == viz::render::hd::kLightDirectional; }
    glm::dvec3 lightPos() const { return glm::dvec3(light.position); }

    // The line of points (eye-relative) that project to data uv `uv` of face `face`: origin, direction.
    void lineOf(glm::dvec2 uv, int face, glm::dvec3& origin, glm::dvec3& dir) const {
        const glm::dvec2 ndc = uv * 2.0 - 1.0;
        if (cube()) {
            const int axis = face >> 1;
            const double s = (face & 1) == 0 ? 1.0 : -1.0;
            glm::dvec3 forward(0.0);
            forward[axis] = s;
            const glm::dvec3 up = axis == 1 ? glm::dvec3(0.0, 0.0, s) : glm::dvec3(0.0, -1.0, 0.0);
            const glm::dvec3 right = glm::cross(forward, up), trueUp = glm::cross(right, forward);
            origin = lightPos();
            dir = glm::normalize(forward + ndc.x * right + ndc.y * trueUp);
            return;
        }
        const glm::dmat4 inv = glm::inverse(glm::dmat4(light.shadowMatrix));
        const glm::dvec4 a = inv * glm::dvec4(ndc, -1.0, 1.0), b = inv * glm::dvec4(ndc, 1.0, 1.0);
        origin = glm::dvec3(a) / a.w;
        dir = glm::normalize(glm::dvec3(b) / b.w - origin);
    }

    // The point of the eye ray t w closest to the line of `uv`: where the mark stands in space.
    glm::dvec3 rayPointAt(const glm::dvec3& w, glm::dvec2 uv, int face) const {
        glm::dvec3 o, d;
        lineOf(uv, face, o, d);
        // Closest approach of t w and o + s d.
        const double b = glm::dot(w, d), c = glm::dot(w, o), e = glm::dot(d, o);
        const double t = (c - b * e) / (1.0 - b * b);
        return t * w;
    }

    bool occluded(const viz::reference::RayTracer& tracer, const glm::dvec3& p) const {
        const glm::dvec3 world = p + scene->camera.position;
        if (directional()) return tracer.occludedRay(world, -glm::dvec3(light.direction));
        return tracer.occludedSegment(world, lightPos() + scene->camera.position);
    }

    // Whether a true lit/shadow boundary passes within one texel of the mark at `uv` on the eye ray: among
    // the points at the mark's distance (depth) from the light in the 3 x 3 texels around it, the
    // reference's ray tracer finds both states.
    bool boundaryWithinATexel(const viz::reference::RayTracer& tracer, const glm::dvec3& w, glm::dvec2 uv,
                              int face) const {
        const glm::dvec3 p = rayPointAt(w, uv, face);
        bool lit = false, shadowed = false;
        for (int j = -1; j <= 1; ++j) {
            for (int i = -1; i <= 1; ++i) {
                glm::dvec3 o, d;
                lineOf(uv + glm::dvec2(i, j) / double(size), face, o, d);
                glm::dvec3 q;
                if (directional()) {
                    const glm::dvec3 dir(light.direction);
                    q = o + d * (glm::dot(p - o, dir) / glm::dot(d, dir));
                } else {
                    q = o + d * glm::length(p - o);
                }
                (occluded(tracer, q) ? shadowed : lit) = true;
            }
        }
        return lit && shadowed;
    }
};

class ShadowMapMarkersTest : public viz::testing::TechniqueTest {
protected:
    std::unique_ptr<viz::Technique> run(const viz::scene::Scene& scene, const std::string& technique,
                                        viz::Settings settings) {
        auto t = viz::makeTechnique(technique);
        viz::testing::runTechnique(*t, scene, settings, kWidth, kHeight);
        return t;
    }

    // Light 0's marks for pixel `px`: the segment against the light's matrix, every lit/shadow change
    // within a texel of a true boundary; with `sameCount`, as many changes as the reference finds, in the
    // same directions. Returns the number of changes marked.
    static int checkMarks(const viz::scene::Scene& scene, const viz::Technique& technique, const std::string& id,
                          glm::ivec2 px, bool sameCount) {
        const std::vector<ViewMarker> marks = technique.markersFor(px, id);
        const viz::reference::RayProbe probe = viz::reference::probePixel(scene, kWidth, kHeight, px.x, px.y);
        const viz::reference::RayTracer tracer(scene);
        const viz::render::GpuLights lights(scene, scene.camera.position, 1);
        const MapModel model{&scene, lights.lights()[0], kMapSize};
        EXPECT_FALSE(marks.empty());
        if (marks.empty()) return 0;
        const glm::dvec3 w = probe.direction;
        if (!model.cube()) {
            // The segment ends at the surface point p(d) (inside the map's frustum in these scenes) ...
            bool inside = false;
            const glm::dvec2 endUv = mapUv2D(model.light, probe.d * w, &inside);
            EXPECT_TRUE(inside);
            const ViewMarker& segment = marks.front();
            EXPECT_NE(segment.from, segment.to);
            EXPECT_EQ(segment.layer, -1);
            EXPECT_NEAR(segment.to.x, endUv.x, 0.5 / kMapSize);
            EXPECT_NEAR(segment.to.y, endUv.y, 0.5 / kMapSize);
            // ... and starts where the ray enters the frustum (bisection on the projection) or at the eye.
            bool eyeInside = false;
            mapUv2D(model.light, 1e-9 * w, &eyeInside);
            double lo = 0.0, hi = eyeInside ? 0.0 : probe.d;
            for (int k = 0; k < 80 && !eyeInside; ++k) {
                const double mid = 0.5 * (lo + hi);
                bool in = false;
                mapUv2D(model.light, mid * w, &in);
                (in ? hi : lo) = mid;
            }
            const glm::dvec2 startUv = mapUv2D(model.light, hi * w);
            EXPECT_NEAR(segment.from.x, startUv.x, 1e-4);
            EXPECT_NEAR(segment.from.y, startUv.y, 1e-4);
        } else {
            // Every mark names its face; the last segment ends at p(d) in the face the lookup picks.
            const ViewMarker* last = nullptr;
            for (const ViewMarker& m : marks) {
                EXPECT_GE(m.layer, 0);
                EXPECT_LT(m.layer, 6);
                if (m.from != m.to) last = &m;
            }
            EXPECT_NE(last, nullptr);
            int face = -1;
            const glm::dvec2 endUv = cubeUv(probe.d * w - model.lightPos(), face);
            if (last) {
                EXPECT_EQ(last->layer, face);
                EXPECT_NEAR(last->to.x, endUv.x, 0.5 / kMapSize);
                EXPECT_NEAR(last->to.y, endUv.y, 0.5 / kMapSize);
            }
        }
        const std::vector<const ViewMarker*> got = points(marks);
        for (const ViewMarker* m : got) {
            const int face = model.cube() ? m->layer : 0;
            EXPECT_TRUE(model.boundaryWithinATexel(tracer, w, glm::dvec2(m->from), face))
                << id << " pixel (" << px.x << ", " << px.y << "): " << m->label;
        }
        if (sameCount) {
            const std::vector<Transition> expected = referenceTransitions(probe, 0);
            EXPECT_EQ(got.size(), expected.size()) << id << " pixel (" << px.x << ", " << px.y << ")";
            for (std::size_t i = 0; i < std::min(got.size(), expected.size()); ++i)
                EXPECT_EQ(labelSaysEnters(*got[i]), expected[i].entersShadow) << got[i]->label;
        }
        return int(got.size());
    }
};

// Floor points under the grate whose rays cross bar shadows (slanted across the bars' stripes) and the
// cube's shadow, and one in a shaft near the middle.
const glm::dvec3 kFloorPoints[] = {{1.5, 0.0, 0.0}, {-1.2, 0.0, -0.5}, {0.1, 0.0, 0.4}};

TEST_F(ShadowMapMarkersTest, SpotMapMarksTheEyeRayAndItsShadowChangesWhereTheReferenceHasThem) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    auto raymarch = run(scene, "raymarch", {{"shadow_map", kMapSize}, {"samples", 8}});
    int total = 0;
    for (const glm::dvec3& p : kFloorPoints)
        total += checkMarks(scene, *raymarch, "raymarch.shadow_map", pixelOf(scene.camera, p), true);
    EXPECT_GE(total, 4);  // the rays do cross bar shadows
}

TEST_F(ShadowMapMarkersTest, DirectionalMapMarksItsShadowChangesWhereTheReferenceHasThem) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    // The sun nearly straight down through the grate. Its map spans the scene's bounding sphere (texels
    // of 5 cm at 256^2), which splits the cube's grazing shadow edges into more changes than the
    // reference has: only the position of each change is checked.
    scene.lights[0].type = viz::scene::LightType::Directional;
    scene.lights[0].direction = glm::normalize(glm::dvec3(0.15, -1.0, 0.05));
    auto raymarch = run(scene, "raymarch", {{"shadow_map", kMapSize}, {"samples", 8}});
    int total = 0;
    for (const glm::dvec3& p : kFloorPoints)
        total += checkMarks(scene, *raymarch, "raymarch.shadow_map", pixelOf(scene.camera, p), false);
    EXPECT_GE(total, 4);
}

TEST_F(ShadowMapMarkersTest, PointLightCubeMarksCarryTheirFaceAndAgreeWithTheReference) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    scene.lights[0].type = viz::scene::LightType::Point;
    auto raymarch = run(scene, "raymarch", {{"shadow_map", kMapSize}, {"samples", 8}});
    int total = 0;
    for (const glm::dvec3& p : kFloorPoints)
        total += checkMarks(scene, *raymarch, "raymarch.shadow_map", pixelOf(scene.camera, p), true);
    EXPECT_GE(total, 4);
}

TEST_F(ShadowMapMarkersTest, NoMarksOutsideTheFrameOrInOtherViews) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    auto raymarch = run(scene, "raymarch", {{"shadow_map", 64}, {"samples", 4}});
    const glm::ivec2 inside = pixelOf(scene.camera, {1.5, 0.0, 0.0});
    EXPECT_FALSE(raymarch->markersFor(inside, "raymarch.shadow_map").empty());
    EXPECT_TRUE(raymarch->markersFor({-1, 10}, "raymarch.shadow_map").empty());
    EXPECT_TRUE(raymarch->markersFor({kWidth, 10}, "raymarch.shadow_map").empty());
    EXPECT_TRUE(raymarch->markersFor({10, kHeight}, "raymarch.shadow_map").empty());
    EXPECT_TRUE(raymarch->markersFor(inside, "raymarch.distance").empty());
    EXPECT_TRUE(raymarch->markersFor(inside, "raymarch.shadow_map.1").empty());  // one light only
    EXPECT_TRUE(raymarch->markersFor(inside, "minmax.shadow_map").empty());
    // A ray that misses the spot's frustum (the top left corner looks above the light) has no marks.
    EXPECT_TRUE(raymarch->markersFor({0, 0}, "raymarch.shadow_map").empty());

    // Stopped after the shadow maps (no distance d yet): the ray runs on to the far end of the map.
    const std::vector<ViewMarker> full = raymarch->markersFor(inside, "raymarch.shadow_map");
    auto early = viz::makeTechnique("raymarch");
    viz::testing::runTechnique(*early, scene, {{"shadow_map", 64}, {"samples", 4}}, kWidth, kHeight, 0);
    const std::vector<ViewMarker> partial = early->markersFor(inside, "raymarch.shadow_map");
    ASSERT_FALSE(partial.empty());
    double t0 = 0.0, tFull = 0.0, tPartial = 0.0;
    ASSERT_EQ(std::sscanf(full[0].label.c_str(), "eye ray t=%lf..%lf", &t0, &tFull), 2);
    ASSERT_EQ(std::sscanf(partial[0].label.c_str(), "eye ray t=%lf..%lf", &t0, &tPartial), 2);
    EXPECT_GT(tPartial, tFull);
    EXPECT_EQ(partial[0].from, full[0].from);
}

// The GPU techniques with shared shadow maps return the same marks for their own maps (the same lights and
// map size), beside their own marks.
TEST_F(ShadowMapMarkersTest, EveryGpuTechniqueMarksItsShadowMaps) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::Settings common = {{"shadow_map", 128}};
    auto raymarch = run(scene, "raymarch", {{"shadow_map", 128}, {"samples", 4}});
    const glm::ivec2 px = pixelOf(scene.camera, {1.5, 0.0, 0.0});
    const std::vector<ViewMarker> expected = raymarch->markersFor(px, "raymarch.shadow_map");
    ASSERT_GE(expected.size(), 2u);
    for (const std::string id : {"minmax", "vsv", "slices"}) {
        auto t = run(scene, id, common);
        const std::vector<ViewMarker> marks = t->markersFor(px, id + ".shadow_map");
        ASSERT_EQ(marks.size(), expected.size()) << id;
        for (std::size_t i = 0; i < marks.size(); ++i) {
            EXPECT_EQ(marks[i].from, expected[i].from) << id;
            EXPECT_EQ(marks[i].to, expected[i].to) << id;
            EXPECT_EQ(marks[i].label, expected[i].label) << id;
        }
    }
    // polyvol draws the same ray, and the crossings with its light volume instead of the texel test's
    // changes (tests/gl/polyvol_markers_test.cpp).
    auto polyvol = run(scene, "polyvol", common);
    const std::vector<ViewMarker> marks = polyvol->markersFor(px, "polyvol.shadow_map");
    ASSERT_FALSE(marks.empty());
    EXPECT_EQ(marks[0].from, expected[0].from);
    EXPECT_EQ(marks[0].to, expected[0].to);
}

// ivsv: its shared surface term has one VPL cube per area-light node (marks on their faces); the voxel
// slices get the eye ray's column as in vsv; the ISM atlas the ray's curve in the shown VPL's tile.
TEST_F(ShadowMapMarkersTest, IvsvMarksItsVplCubesVoxelSlicesAndIsmTile) {
    const viz::scene::Scene scene = viz::scene::makeTestAreaLightScene();
    auto ivsv = run(scene, "ivsv", {{"shadow_map", 32}, {"vpls", 4}, {"voxels", 32}, {"area_samples", 1}});
    const glm::ivec2 px = pixelOf(scene.camera, {0.3, 0.0, 0.5});
    const std::vector<ViewMarker> marks = ivsv->markersFor(px, "ivsv.shadow_map");
    ASSERT_FALSE(marks.empty());
    for (const ViewMarker& m : marks) EXPECT_GE(m.layer, 0);

    // The slices show the theta cell of the picked pixel (default: the image centre): its eye ray is a
    // full-height column inside the slice.
    const glm::ivec2 centre{kWidth / 2, kHeight / 2};
    for (const std::string id : {"ivsv.voxels", "ivsv.scanned"}) {
        const std::vector<ViewMarker> column = ivsv->markersFor(centre, id);
        ASSERT_EQ(column.size(), 1u) << id;
        EXPECT_EQ(column[0].from.x, column[0].to.x);
        EXPECT_GT(column[0].from.x, 0.0f);
        EXPECT_LT(column[0].from.x, 1.0f);
        EXPECT_EQ(column[0].from.y, 0.0f);
        EXPECT_EQ(column[0].to.y, 1.0f);
    }

    // 4 VPLs: a 2 x 2 atlas; VPL 0's tile is the lower left quarter (GL rows). The curve is a connected
    // polyline inside it, labelled once.
    const std::vector<ViewMarker> curve = ivsv->markersFor(centre, "ivsv.ism");
    ASSERT_GE(curve.size(), 2u);
    EXPECT_FALSE(curve[0].label.empty());
    for (std::size_t i = 0; i < curve.size(); ++i) {
        for (const glm::vec2 p : {curve[i].from, curve[i].to}) {
            EXPECT_GE(p.x, 0.0f);
            EXPECT_LE(p.x, 0.5f);
            EXPECT_GE(p.y, 0.0f);
            EXPECT_LE(p.y, 0.5f);
        }
        if (i > 0) {
            EXPECT_EQ(curve[i].from, curve[i - 1].to);
            EXPECT_TRUE(curve[i].label.empty());
        }
    }
    EXPECT_EQ(ivsv->markersFor(centre, "ivsv.ism_splatted").size(), curve.size());
    EXPECT_TRUE(ivsv->markersFor({-1, 0}, "ivsv.ism").empty());
    EXPECT_TRUE(ivsv->markersFor(centre, "ivsv.airlight").empty());
}

}  // namespace
