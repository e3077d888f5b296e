// polyvol on pixels whose ray passes 1e-4 from a spot light's apex (sigma_t = 0.1, the light in view,
// nothing in between): the picked pixel against the reference technique and against a quadrature of the
// airlight integral along the same ray computed here in long double (Boost.Math Gauss-Kronrod), which
// shares no code with either.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "scene/builtin_scenes.h"
#include "scene/scene_building.h"
#include "technique_test_util.h"

namespace {

class PolyvolNearLight : public viz::testing::TechniqueTest {};

using Real = long double;

const glm::dvec3 kApex{0.0, 6.0, 0.0};
constexpr double kPass = 1e-4;  // the centre pixel's ray passes this far from the apex

// grate without its bars and its cube: a floor, the spot at (0, 6, 0) shining down (inner 0.40, outer
// 0.55 rad, 400 cd, white), sigma_s = 0.1, sigma_a = 0. The camera at `eye` aims at a point kPass from the
// apex, perpendicular to the line of sight, so the centre pixel's ray (odd image size: the camera's
// forward ray) passes the apex at kPass.
viz::scene::Scene nearLightScene(glm::dvec3 eye, glm::dvec3 side) {
    viz::scene::Scene s = viz::scene::makeBuiltinScene("grate");
    std::erase_if(s.meshes, [](const viz::scene::Mesh& m) { return m.name == "grate" || m.name == "cube"; });
    s.lights[0].colour = {1.0, 1.0, 1.0};
    s.medium = viz::scene::Medium{0.1, 0.0, 0.0};
    const glm::dvec3 toApex = glm::normalize(kApex - eye);
    const glm::dvec3 n = glm::normalize(side - glm::dot(side, toApex) * toApex);
    s.camera = viz::scene::lookAt("near-apex", eye, kApex + kPass * n, 0.9, 0.05, 40.0);
    return s;
}

// L_air (red channel) along the ray from the camera in direction w over [0, inf), in the angle phi = atan(s / h) seen
// from the light (s: position along the ray from the foot point P): dx / r^2 = dphi / h, the direction
// from the light is (m / h) cos(phi) + w sin(phi) (m = P - light), x + r = tP + h tan(pi/4 + phi/2), and
// cos(theta_s) = -sin(phi). A_spot = clamp(cos * scale + offset, 0, 1)^2 (KHR_lights_punctual) has kinks
// where the ray crosses the inner and outer cones: found in closed form and used as break points.
Real quadratureAlongTheRay(const viz::scene::Scene& s, glm::dvec3 w) {
    const viz::scene::Light& L = s.lights[0];
    const glm::dvec3 D = L.position - s.camera.position;
    const Real tP = glm::dot(D, w), h = glm::length(glm::cross(D, w));
    const glm::dvec3 m = s.camera.position + double(tP) * w - L.position;
    const glm::dvec3 a = L.direction;
    const Real ma = glm::dot(m, a) / double(h), wa = glm::dot(w, a);
    const Real cosOuter = std::cos(Real(L.outerConeAngle)), cosInner = std::cos(Real(L.innerConeAngle));
    const Real scale = 1 / std::max(Real(0.001), cosInner - cosOuter), offset = -cosOuter * scale;
    const Real sigma_s = s.medium.sigma_s, sigma_t = s.medium.sigma_t(), I = L.intensity * L.colour.r;
    const Real pi = boost::math::constants::pi<Real>();
    auto f = [&](Real phi) -> Real {
        const Real cd = ma * std::cos(phi) + wa * std::sin(phi);
        const Real spot = std::clamp(cd * scale + offset, Real(0), Real(1));
        if (spot == 0) return 0;
        const Real opticalPath = sigma_t * (tP + h * std::tan(pi / 4 + phi / 2));
        return sigma_s * I * spot * spot / (4 * pi) * std::exp(-opticalPath) / h;
    };
    const Real phi0 = -std::atan2(tP, h), phi1 = pi / 2;
    std::vector<Real> breaks{phi0, phi1, Real(0)};
    // cd(phi) = R cos(phi - phi*), R = hypot(ma, wa), phi* = atan2(wa, ma).
    const Real R = std::hypot(ma, wa), phiStar = std::atan2(wa, ma);
    for (Real c : {cosOuter, cosInner})
        if (std::abs(c) <= R)
            for (Real sign : {Real(-1), Real(1)})
                for (Real turn : {Real(-2), Real(0), Real(2)}) breaks.push_back(phiStar + sign * std::acos(c / R) + turn * pi);
    std::erase_if(breaks, [&](Real b) { return !(b >= phi0 && b <= phi1); });
    std::sort(breaks.begin(), breaks.end());
    Real sum = 0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
        if (breaks[i + 1] > breaks[i])
            sum += boost::math::quadrature::gauss_kronrod<Real, 61>::integrate(f, breaks[i], breaks[i + 1], 30, 1e-13L);
    return sum;
}

struct NearLightCase {
    const char* name;
    glm::dvec3 eye;
    glm::dvec3 side;  // the ray passes the apex on this side (perpendicular part)
};

const NearLightCase kCases[] = {
    // Horizontal, 1e-4 below the apex: crosses the cone where it is 1.2e-4 wide. The mesh's crossings
    // there are sub-pixel; polyvol once found none and gave 0.
    {"from the side, through the cone's tip", {0.0, 6.0, 7.0}, {0.0, -1.0, 0.0}},
    // From inside the cone, steeply up past the apex: one crossing (leaving the cone) next to the light.
    {"from inside the cone, steeply up past the apex", {0.3, 1.0, 0.5}, {1.0, 0.0, 0.0}},
    // From inside the cone, obliquely: it leaves the cone next to the apex, and re-enters and leaves the
    // cone's mesh where the cone wall meets the ray's view of the floor.
    {"from inside the cone, obliquely past the apex", {1.5, 2.0, 1.5}, {0.0, 1.0, 0.0}},
};

}  // namespace

// The picked pixel: the reference agrees with the quadrature (checks the quadrature and the scene), and
// polyvol agrees with both within 1 % with the closed form and with the lookup table, at its defaults and
// at its stiff-suite settings. Before the fix: 0 (the cone's tip, both paths), +20 % and +112 % (the lookup
// table on the other two) and +175 % on a ray 1.2e-5 from the apex (README, "Rays next to the light").
TEST_F(PolyvolNearLight, PixelPassingTheApexMatchesTheReferenceAndAQuadrature) {
    const int w = 33, h = 25, x = w / 2, y = h / 2;
    auto* polyvol = viz::makeTechnique("polyvol").release();
    const viz::Settings stiff = polyvol->stiffSettings();
    delete polyvol;
    viz::Settings stiffLut = stiff;
    stiffLut["airlight"] = 1;
    const std::vector<std::pair<const char*, viz::Settings>> variants = {
        {"analytic", {{"shadow_map", 1024}}},
        {"lut", {{"shadow_map", 1024}, {"airlight", 1}}},
        {"analytic, stiff settings", stiff},
        {"lut, stiff settings", stiffLut},
    };
    for (const NearLightCase& c : kCases) {
        SCOPED_TRACE(c.name);
        const viz::scene::Scene scene = nearLightScene(c.eye, c.side);
        const double q = double(quadratureAlongTheRay(scene, scene.camera.forward));
        const double ref = render(scene, "reference", {}, w, h).airlight.at(x, y, 0);
        // What float32 alone costs: the same quadrature along the GPU's float pixel ray (not checked).
        const glm::dvec3 floatRay = glm::normalize(glm::dvec3(viz::testing::shaderPixelRay(scene.camera, w, h, x, y)));
        const double qFloat = double(quadratureAlongTheRay(scene, floatRay));
        std::printf("%s: quadrature %.6g, reference %.6g (%+.1e); along the float ray %.6g (%+.2e)\n", c.name, q, ref,
                    ref / q - 1.0, qFloat, qFloat / q - 1.0);
        ASSERT_GT(q, 10.0);
        EXPECT_LT(std::abs(ref / q - 1.0), 1e-3);
        for (const auto& [label, settings] : variants) {
            const viz::FrameOutput out = render(scene, "polyvol", settings, w, h);
            const double v = out.airlight.at(x, y, 0);
            std::printf("  polyvol %-26s %.6g (%+.2e)\n", label, v, v / q - 1.0);
            EXPECT_TRUE(std::isfinite(v)) << label;
            EXPECT_LT(std::abs(v / q - 1.0), 0.01) << label << ": " << v << " vs " << q;
        }
        // The same pixel ray at 161x121, where the ball around the light is smaller (16 pixel footprints).
        const double fine = render(scene, "polyvol", {{"shadow_map", 1024}}, 161, 121).airlight.at(80, 60, 0);
        std::printf("  polyvol analytic at 161x121    %.6g (%+.2e)\n", fine, fine / q - 1.0);
        EXPECT_LT(std::abs(fine / q - 1.0), 0.01) << "161x121";
    }
}
