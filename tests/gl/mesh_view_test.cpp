// The mesh view (render::MeshView): an orbit camera of its own around the scene and the main camera,
// used by polyvol (wireframe=3) and slices (mesh_view=1) to show their meshes from outside.
#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <vector>

#include "render/gpu_scene.h"
#include "render/mesh_view.h"
#include "scene/builtin_scenes.h"
#include "technique_test_util.h"

namespace {

using viz::render::OrbitView;

glm::dvec3 project(const glm::mat4& viewProj, glm::dvec3 p) {
    const glm::dvec4 c = glm::dmat4(viewProj) * glm::dvec4(p, 1.0);
    return glm::dvec3(c) / c.w;
}

bool inside(glm::dvec3 ndc) { return glm::all(glm::lessThanEqual(glm::abs(ndc), glm::dvec3(1.0))); }

// Pixels of `image` within 0.08 of `colour` (RGB, display values).
int pixelsNear(const viz::Image& image, glm::vec3 colour) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 c(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
            if (glm::all(glm::lessThan(glm::abs(c - colour), glm::vec3(0.08f)))) ++n;
        }
    return n;
}

}  // namespace

// The orbit camera frames the scene and the main camera from every direction: the bounds' corners, the
// main camera's eye and the orbit target stay in the image (depth inside [-1, 1]), the target at its centre.
TEST(MeshView, OrbitCameraFramesTheSceneAndTheCameraFromEveryDirection) {
    for (const std::string name : {"grate", "colonnade", "tv-room"}) {
        const viz::scene::Scene scene = viz::scene::makeBuiltinScene(name);
        const viz::scene::Bounds bounds = viz::scene::sceneBounds(scene);
        const glm::dvec3 eye = scene.camera.position;
        const glm::dvec3 lo = glm::min(bounds.lo, eye), hi = glm::max(bounds.hi, eye);
        for (double yaw : {-170.0, 0.0, 35.0, 120.0})
            for (double pitch : {-60.0, 0.0, 25.0, 85.0}) {
                const glm::mat4 vp = viz::render::orbitViewProjection(scene, bounds, OrbitView{yaw, pitch, 1.0}, 160, 120);
                const glm::dvec3 centre = project(vp, 0.5 * (lo + hi) - eye);
                EXPECT_NEAR(centre.x, 0.0, 1e-5) << name << " " << yaw << " " << pitch;
                EXPECT_NEAR(centre.y, 0.0, 1e-5) << name << " " << yaw << " " << pitch;
                EXPECT_TRUE(inside(project(vp, glm::dvec3(0.0)))) << name << ": the main camera's eye";
                for (int corner = 0; corner < 8; ++corner) {
                    const glm::dvec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
                    EXPECT_TRUE(inside(project(vp, p - eye))) << name << " corner " << corner << " yaw " << yaw
                                                              << " pitch " << pitch;
                }
            }
    }
}

// Scale-free: grate scaled by 1e-9 (a nanometre model) or 1e4 is framed exactly as at scale 1, every
// corner of its box at the same place in the orbit view.
TEST(MeshView, OrbitCameraFramesAModelTheSameAtEveryScale) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::scene::Bounds bounds = viz::scene::sceneBounds(scene);
    auto corners = [&](double s) {
        viz::scene::Scene scaled = scene;
        scaled.camera.position *= s;
        const viz::scene::Bounds box{bounds.lo * s, bounds.hi * s, false};
        const glm::mat4 vp = viz::render::orbitViewProjection(scaled, box, OrbitView{35.0, 25.0, 1.0}, 160, 120);
        const glm::dvec3 eye = scaled.camera.position, lo = glm::min(box.lo, eye), hi = glm::max(box.hi, eye);
        std::vector<glm::dvec3> out;
        for (int corner = 0; corner < 8; ++corner)
            out.push_back(project(vp, glm::dvec3((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z) - eye));
        return out;
    };
    const auto unit = corners(1.0);
    for (double s : {1e-9, 1e-3, 1e4}) {
        const auto scaled = corners(s);
        for (int i = 0; i < 8; ++i) {
            EXPECT_NEAR(scaled[std::size_t(i)].x, unit[std::size_t(i)].x, 1e-4) << "scale " << s << " corner " << i;
            EXPECT_NEAR(scaled[std::size_t(i)].y, unit[std::size_t(i)].y, 1e-4) << "scale " << s << " corner " << i;
        }
    }
}

// The frustum lines start at the eye (eye-relative origin) and reach `depth` along the view.
TEST(MeshView, CameraFrustumLinesRunFromTheEyeToTheRequestedDepth) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const auto lines = viz::render::cameraFrustumLines(scene.camera, 160, 120, 2.0);
    ASSERT_EQ(lines.size(), 16u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(lines[std::size_t(4 * i)], glm::vec3(0.0f));
        EXPECT_NEAR(glm::dot(glm::dvec3(lines[std::size_t(4 * i + 1)]), scene.camera.forward), 2.0, 1e-5);
    }
}

class MeshViewRender : public viz::testing::TechniqueTest {};

// polyvol's wireframe=3 and slices' mesh_view=1 draw into the orbit view: the light marker (yellow),
// the camera frustum (blue) and the technique's mesh all show, and a different yaw gives another image.
TEST_F(MeshViewRender, PolyvolAndSlicesDrawTheirMeshesWithTheCameraAndLight) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const glm::vec3 yellow(1.0f, 0.85f, 0.3f), blue(0.35f, 0.65f, 1.0f);
    const viz::FrameOutput poly =
        render(scene, "polyvol", {{"wireframe", 3}, {"shadow_map", 64}}, 160, 120, -1, {"polyvol.mesh"});
    const viz::Intermediate* mesh = find(poly, "polyvol.mesh");
    ASSERT_TRUE(mesh && mesh->image);
    EXPECT_GT(pixelsNear(*mesh->image, yellow), 3);
    EXPECT_GT(pixelsNear(*mesh->image, blue), 10);
    const int green = pixelsNear(*mesh->image, {0.1f, 0.8f, 0.2f}), red = pixelsNear(*mesh->image, {0.9f, 0.15f, 0.1f});
    EXPECT_GT(green, 20) << "faces where rays leave the volume";
    EXPECT_GT(red, 20) << "faces where rays enter the volume";

    const viz::FrameOutput plainPoly = render(scene, "polyvol", {{"shadow_map", 64}}, 160, 120);
    EXPECT_EQ(plainPoly.airlight.pixels, poly.airlight.pixels) << "the orbit view leaves the volume pass alone";

    const viz::FrameOutput turned = render(scene, "polyvol", {{"wireframe", 3}, {"shadow_map", 64}, {"mesh_yaw", 120}},
                                           160, 120, -1, {"polyvol.mesh"});
    EXPECT_NE(find(turned, "polyvol.mesh")->image->pixels, mesh->image->pixels);

    // The paper's planes (integration=midpoint), each the light volume's cross-section, so the nearest one is
    // large enough to find by its colour; under the slab integral the nearest planes are cut to the view
    // (SliceGeometry.WidenedPolygonsHoldEveryFrustumPointOfTheirSlab checks those polygons).
    const viz::Settings paperPlanes{{"planes", 16}, {"integration", 0}};
    viz::Settings withView = paperPlanes;
    withView["mesh_view"] = 1;
    const viz::FrameOutput slices = render(scene, "slices", withView, 160, 120, -1, {"slices.plane_view"});
    const viz::Intermediate* planes = find(slices, "slices.plane_view");
    ASSERT_TRUE(planes && planes->image);
    EXPECT_GT(pixelsNear(*planes->image, blue), 10);
    // The nearest plane's outline is drawn in (1, 0.85, 0.2): the brightest of the plane colours.
    EXPECT_GT(pixelsNear(*planes->image, {1.0f, 0.85f, 0.2f}), 10);
    // The airlight is the same with or without the view.
    const viz::FrameOutput plain = render(scene, "slices", paperPlanes, 160, 120);
    EXPECT_EQ(plain.airlight.pixels, slices.airlight.pixels);
}

// Shown, polyvol's light volume mesh has a picture without any setting: asked for as a view
// (FrameInput::views, as the window does for the views in its grid), the volume stage draws the orbit
// view; not asked for, it draws nothing (the report's timed runs pay nothing for it). The airlight is
// the same either way.
TEST_F(MeshViewRender, PolyvolDrawsItsOrbitViewWhenTheCallerShowsTheMesh) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    auto polyvol = viz::makeTechnique("polyvol");
    viz::FrameInput in = viz::frameInput(&scene, 160, 120, viz::completeSettings(*polyvol, {{"shadow_map", 64}}));
    const viz::FrameOutput plain = polyvol->run(in);
    const viz::Intermediate* bare = find(plain, "polyvol.mesh");
    ASSERT_TRUE(bare);
    EXPECT_EQ(bare->glTexture, 0u);
    EXPECT_EQ(bare->kind, viz::ViewKind::Mesh);
    const viz::Image airlight = plain.airlight;

    in.views = {"polyvol.mesh"};
    const viz::FrameOutput shown = polyvol->run(in);
    const viz::Intermediate* mesh = find(shown, "polyvol.mesh");
    ASSERT_TRUE(mesh && mesh->glTexture != 0);
    EXPECT_TRUE(mesh->orbit);
    const viz::Image picture = viz::gl::readTexture(mesh->glTexture);
    EXPECT_GT(pixelsNear(picture, {0.35f, 0.65f, 1.0f}), 10) << "the camera frustum";
    EXPECT_GT(pixelsNear(picture, {0.9f, 0.15f, 0.1f}), 20) << "faces where rays enter the volume";
    EXPECT_NE(mesh->note.find("this view is shown"), std::string::npos) << mesh->note;
    EXPECT_EQ(shown.airlight.pixels, airlight.pixels);
}

// slices' planes' table (slices.plane_mesh) is a vertex list, a row per plane; shown (FrameInput::views),
// the planes stage draws it as the orbit view of the planes' outlines instead, as polyvol does its mesh
// (a table stretched into an image says nothing), with mesh_view=0 and under the table's own id.
TEST_F(MeshViewRender, SlicesDrawsThePlanesAsAnOrbitViewWhenTheCallerShowsTheirTable) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    auto slices = viz::makeTechnique("slices");
    viz::FrameInput in = viz::frameInput(&scene, 160, 120, viz::completeSettings(*slices, {{"planes", 16}}));
    const viz::FrameOutput plain = slices->run(in);
    const viz::Intermediate* table = find(plain, "slices.plane_mesh");
    ASSERT_TRUE(table && table->image);
    EXPECT_EQ(table->kind, viz::ViewKind::Mesh);
    EXPECT_EQ(table->image->height, 16) << "a row per plane drawn";
    EXPECT_FALSE(table->orbit);
    const viz::Image airlight = plain.airlight;

    in.views = {"slices.plane_mesh"};
    const viz::FrameOutput shown = slices->run(in);
    const viz::Intermediate* view = find(shown, "slices.plane_mesh");
    ASSERT_TRUE(view && view->glTexture != 0);
    EXPECT_TRUE(view->orbit && view->picture);
    EXPECT_EQ(find(shown, "slices.plane_view"), nullptr) << "mesh_view=0: the orbit view only under the table's id";
    EXPECT_NE(view->note.find("this view is shown"), std::string::npos) << view->note;
    const viz::Image picture = viz::gl::readTexture(view->glTexture);
    EXPECT_GT(pixelsNear(picture, {0.35f, 0.65f, 1.0f}), 10) << "the camera frustum";
    EXPECT_EQ(shown.airlight.pixels, airlight.pixels);
}
