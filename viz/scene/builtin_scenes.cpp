#include "scene/builtin_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/error.h"
#include "scene/area_light.h"
#include "scene/scene_building.h"

namespace viz::scene {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- deterministic helpers ----

// xorshift64*: fixed seeds make every built-in scene identical across runs and platforms.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : mState(seed ? seed : 1) {}
    double uniform() {  // [0, 1)
        mState ^= mState >> 12;
        mState ^= mState << 25;
        mState ^= mState >> 27;
        return double((mState * 0x2545F4914F6CDD1DULL) >> 11) * (1.0 / 9007199254740992.0);
    }
    double range(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
    std::uint64_t mState;
};

glm::dvec3 unit(glm::dvec3 v) { return glm::normalize(v); }

int addMaterial(Scene& scene, const std::string& name, glm::vec3 albedo, int texture = -1) {
    Material m;
    m.name = name;
    m.baseColorFactor = glm::vec4(albedo, 1.0f);
    m.baseColorTexture = texture;
    scene.materials.push_back(m);
    return int(scene.materials.size() - 1);
}

void addMesh(Scene& scene, MeshBuilder& builder) { scene.meshes.push_back(builder.take()); }

Light spotLight(const std::string& name, glm::dvec3 position, glm::dvec3 target, double intensity, glm::dvec3 colour,
                double inner, double outer) {
    Light l;
    l.name = name;
    l.type = LightType::Spot;
    l.position = position;
    l.direction = unit(target - position);
    l.intensity = intensity;
    l.colour = colour;
    l.innerConeAngle = inner;
    l.outerConeAngle = outer;
    return l;
}

Light sunLight(const std::string& name, glm::dvec3 travel, double lux, glm::dvec3 colour) {
    Light l;
    l.name = name;
    l.type = LightType::Directional;
    l.direction = unit(travel);
    l.intensity = lux;
    l.colour = colour;
    return l;
}

// ---- textures ----

Texture makeTexture(const std::string& name, int w, int h) {
    Texture t;
    t.name = name;
    t.width = w;
    t.height = h;
    t.rgba8.assign(std::size_t(w) * std::size_t(h) * 4, 255);
    return t;
}

void setTexel(Texture& t, int x, int y, glm::dvec3 rgb) {
    const std::size_t i = (std::size_t(y) * std::size_t(t.width) + std::size_t(x)) * 4;
    for (int c = 0; c < 3; ++c) t.rgba8[i + std::size_t(c)] = std::uint8_t(std::lround(std::clamp(rgb[c], 0.0, 1.0) * 255.0));
}

Texture checkerTexture(const std::string& name, int size, int cells, glm::dvec3 a, glm::dvec3 b) {
    Texture t = makeTexture(name, size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) setTexel(t, x, y, ((x * cells / size + y * cells / size) % 2) ? a : b);
    }
    return t;
}

// Stained glass: Voronoi cells of saturated colours separated by dark lead lines, inside a round
// window (black outside the circle, so the spot's footprint is a disc).
Texture stainedGlassTexture() {
    const int size = 64;
    Texture t = makeTexture("stained_glass", size, size);
    Rng rng(20240611);
    std::vector<glm::dvec2> seeds(18);
    std::vector<glm::dvec3> colours(seeds.size());
    const glm::dvec3 palette[6] = {{0.95, 0.2, 0.15}, {0.15, 0.35, 0.95}, {0.98, 0.8, 0.15},
                                   {0.2, 0.8, 0.3},   {0.7, 0.25, 0.85}, {0.95, 0.55, 0.15}};
    for (std::size_t i = 0; i < seeds.size(); ++i) {
        seeds[i] = {rng.uniform(), rng.uniform()};
        colours[i] = palette[i % 6];
    }
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::dvec2 p((x + 0.5) / size, (y + 0.5) / size);
            double d1 = 1e9, d2 = 1e9;
            std::size_t nearest = 0;
            for (std::size_t i = 0; i < seeds.size(); ++i) {
                const double d = glm::length(p - seeds[i]);
                if (d < d1) {
                    d2 = d1;
                    d1 = d;
                    nearest = i;
                } else if (d < d2) {
                    d2 = d;
                }
            }
            const double r = glm::length(p - glm::dvec2(0.5));
            glm::dvec3 rgb = colours[nearest];
            if (d2 - d1 < 0.025 || std::abs(r - 0.47) < 0.02) rgb = glm::dvec3(0.02);  // lead
            if (r > 0.49) rgb = glm::dvec3(0.0);
            setTexel(t, x, y, rgb);
        }
    }
    return t;
}

// TV picture: colour bars over the top two thirds, a grey ramp below, and a bright disc.
Texture tvTexture() {
    const int w = 64, h = 36;
    Texture t = makeTexture("tv_picture", w, h);
    const glm::dvec3 bars[7] = {{0.75, 0.75, 0.75}, {0.75, 0.75, 0}, {0, 0.75, 0.75}, {0, 0.75, 0},
                                {0.75, 0, 0.75},    {0.75, 0, 0},    {0, 0, 0.75}};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            glm::dvec3 rgb = y < 24 ? bars[x * 7 / w] : glm::dvec3(double(x) / (w - 1));
            const double dx = (x + 0.5) - 44.0, dy = (y + 0.5) - 12.0;
            if (dx * dx + dy * dy < 36.0) rgb = glm::dvec3(1.0);
            setTexel(t, x, y, rgb);
        }
    }
    return t;
}

// ---- scenes ----

Scene grate(double detail) {
    Scene s;
    s.name = "grate";
    const int floorMat = addMaterial(s, "floor", {0.6f, 0.6f, 0.6f});
    const int ironMat = addMaterial(s, "iron", {0.3f, 0.3f, 0.32f});
    const int cubeMat = addMaterial(s, "cube", {0.7f, 0.3f, 0.25f});

    MeshBuilder floor("floor", floorMat);
    floor.quad({-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5});
    addMesh(s, floor);

    // Grate at y = 3 over x, z in [-2, 2]: 10 bars along z (pitch 0.4 m, 0.24 m gaps) and 2 cross bars.
    // With detail k, 10k bars at pitch 0.4/k m, each 0.16/k m wide: the same open fraction, k times the
    // triangles.
    MeshBuilder bars("grate", ironMat);
    const int barCount = int(std::lround(10.0 * detail));
    const double pitch = 4.0 / barCount;
    for (int i = 0; i < barCount; ++i) {
        // detail 1 keeps the original expressions, so that the default scene is bit for bit the same.
        const double x = detail == 1.0 ? -1.8 + 0.4 * i : -2.0 + pitch * (i + 0.5);
        bars.box({x, 3.0, 0.0}, {detail == 1.0 ? 0.08 : 0.2 * pitch, 0.05, 2.0});
    }
    for (double z : {-1.2, 1.2}) bars.box({0.0, 3.0, z}, {2.0, 0.05, 0.08});
    addMesh(s, bars);

    MeshBuilder cube("cube", cubeMat);
    cube.box({1.2, 0.5, 0.6}, {0.5, 0.5, 0.5}, 0.4);
    addMesh(s, cube);

    // The outer cone's radius at the grate is 3 * tan(0.55) = 1.84 m < 2 m: all its light crosses it.
    s.lights.push_back(spotLight("spot", {0, 6, 0}, {0, 0, 0}, 400.0, {1.0, 0.92, 0.8}, 0.40, 0.55));
    s.medium = Medium{0.12, 0.01, 0.2};
    s.camera = lookAt("side", {0.0, 0.8, 7.0}, {0.0, 2.0, 0.0}, 0.9, 0.05, 40.0);
    return s;
}

Scene colonnade() {
    Scene s;
    s.name = "colonnade";
    s.textures.push_back(checkerTexture("floor_tiles", 64, 16, {0.85, 0.82, 0.75}, {0.55, 0.5, 0.45}));
    const int floorMat = addMaterial(s, "floor", {1.0f, 1.0f, 1.0f}, 0);
    const int stoneMat = addMaterial(s, "stone", {0.75f, 0.72f, 0.66f});
    const int pillarMat = addMaterial(s, "pillar", {0.8f, 0.78f, 0.72f});

    // Hall interior: x in [-10, 10], y in [0, 6], z in [-6, 6]; the window wall is z in [-6.4, -6].
    MeshBuilder floor("floor", floorMat);
    floor.quad({-10, 0, 6}, {10, 0, 6}, {10, 0, -6.4}, {-10, 0, -6.4});
    addMesh(s, floor);

    // The roof: a slab 0.5 m thick whose underside is the ceiling. A single quad there let the shadow
    // map's bias light a line along the top of the east wall and a band of air under the ceiling: a
    // receiver within the bias of the occluder reads lit. (The stiff case sun-grazing-ceiling puts the
    // quad back: it tests that leak.)
    MeshBuilder roof("roof", stoneMat);
    roof.box({0, 6.25, -0.2}, {10, 0.25, 6.2});
    addMesh(s, roof);

    MeshBuilder shell("walls", stoneMat);
    shell.quad({10, 0, -6.4}, {10, 0, 6}, {10, 6, 6}, {10, 6, -6.4});    // east, facing -x
    shell.quad({-10, 0, 6}, {-10, 0, -6.4}, {-10, 6, -6.4}, {-10, 6, 6});  // west, facing +x
    shell.quad({10, 0, 6}, {-10, 0, 6}, {-10, 6, 6}, {10, 6, 6});        // south, facing -z
    // North wall with five windows 1.6 m wide, from y = 1.2 to 5.0, centred at x = -8, -4, 0, 4, 8.
    shell.box({0, 0.6, -6.2}, {10, 0.6, 0.2});
    shell.box({0, 5.5, -6.2}, {10, 0.5, 0.2});
    const double piers[6][2] = {{-10, -8.8}, {-7.2, -4.8}, {-3.2, -0.8}, {0.8, 3.2}, {4.8, 7.2}, {8.8, 10}};
    for (const auto& p : piers) shell.box({0.5 * (p[0] + p[1]), 3.1, -6.2}, {0.5 * (p[1] - p[0]), 1.9, 0.2});
    addMesh(s, shell);

    MeshBuilder pillars("pillars", pillarMat);
    for (int i = 0; i < 6; ++i) pillars.box({-7.5 + 3.0 * i, 3.0, -3.0}, {0.35, 3.0, 0.35}, kPi / 4);
    addMesh(s, pillars);

    // Sun travelling into the hall (+z) and down; it enters only through the windows. The camera looks
    // back towards the windows, across the shafts and into the forward-scattering lobe.
    s.lights.push_back(sunLight("sun", {0.45, -0.5, 1.0}, 10.0, {1.0, 0.9, 0.75}));
    s.medium = Medium{0.1, 0.01, 0.4};
    s.camera = lookAt("hall", {-8.5, 1.6, 5.2}, {1.0, 2.6, -6.0}, 0.95, 0.05, 50.0);
    return s;
}

Scene forest(double detail) {
    Scene s;
    s.name = "forest";
    const int groundMat = addMaterial(s, "ground", {0.35f, 0.3f, 0.2f});
    const int barkMat = addMaterial(s, "bark", {0.3f, 0.22f, 0.15f});

    MeshBuilder ground("ground", groundMat);
    ground.quad({-30, 0, 30}, {30, 0, 30}, {30, 0, -30}, {-30, 0, -30});
    addMesh(s, ground);

    // 320 trunks, 0.2-0.4 m thick and 10 m tall, kept out of a clearing around the camera. With detail k,
    // 320k trunks 1/sqrt(k) as thick: about the same ground covered, k times the triangles.
    MeshBuilder trunks("trunks", barkMat);
    Rng rng(7);
    int placed = 0;
    const int trunkCount = int(std::lround(320.0 * detail));
    const double thickness = 1.0 / std::sqrt(detail);
    while (placed < trunkCount) {
        const double x = rng.range(-26, 26), z = rng.range(-26, 26);
        const double r = rng.range(0.1, 0.2) * thickness, yaw = rng.range(0.0, kPi);
        if (glm::length(glm::dvec2(x - 18.0, z - 6.0)) < 6.0) continue;
        trunks.box({x, 5.0, z}, {r, 5.0, r}, yaw);
        ++placed;
    }
    addMesh(s, trunks);

    // A low sun in front of the camera: shafts are the trunks' shadows in the air, seen against it.
    s.lights.push_back(sunLight("sun", {1.0, -0.55, 0.25}, 4.0, {1.0, 0.85, 0.65}));
    s.medium = Medium{0.012, 0.003, 0.45};
    s.camera = lookAt("clearing", {18.0, 1.7, 6.0}, {-10.0, 4.0, -2.0}, 0.9, 0.05, 80.0);
    return s;
}

double terrainHeight(double x, double z) {
    return 4.0 * std::sin(0.16 * x + 0.5) * std::cos(0.12 * z - 0.3) + 1.2 * std::sin(0.27 * x + 0.21 * z + 1.0) +
           0.5 * std::sin(0.61 * x - 0.43 * z) + 1.5 * std::exp(-0.01 * (x + 5.0) * (x + 5.0)) * 2.0;
}

Scene terrain(double detail) {
    Scene s;
    s.name = "terrain";
    const int groundMat = addMaterial(s, "terrain", {0.45f, 0.42f, 0.35f});
    // A 64 x 64 grid of samples; with detail k, about sqrt(k) times as many along each side.
    const int n = detail == 1.0 ? 64 : 1 + int(std::lround(63.0 * std::sqrt(detail)));
    const double extent = 30.0, step = 2.0 * extent / (n - 1);
    MeshBuilder builder("heightfield", groundMat);
    Mesh& mesh = builder.mesh();
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const double x = -extent + step * i, z = -extent + step * j;
            mesh.positions.push_back(glm::vec3(glm::dvec3(x, terrainHeight(x, z), z)));
            // Normal of the heightfield y = h(x, z): (-dh/dx, 1, -dh/dz), by central differences.
            const double e = 1e-3;
            const double dhdx = (terrainHeight(x + e, z) - terrainHeight(x - e, z)) / (2 * e);
            const double dhdz = (terrainHeight(x, z + e) - terrainHeight(x, z - e)) / (2 * e);
            mesh.normals.push_back(glm::vec3(unit({-dhdx, 1.0, -dhdz})));
            mesh.uvs.push_back(glm::vec2(float(i) / (n - 1), float(j) / (n - 1)));
        }
    }
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            const auto a = std::uint32_t(j * n + i), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
            // Counter-clockwise seen from above (+Y): a (x, z), c (x, z + dz), b (x + dx, z).
            for (std::uint32_t k : {a, c, b, b, c, d}) mesh.indices.push_back(k);
        }
    }
    addMesh(s, builder);

    // The sun crosses the view from the side, low enough for the ridges to cast long shadow volumes.
    s.lights.push_back(sunLight("sun", {0.25, -0.2, 1.0}, 5.0, {1.0, 0.8, 0.6}));
    s.medium = Medium{0.02, 0.002, 0.3};
    const double camX = 26.0, camZ = 4.0;
    s.camera = lookAt("ridge", {camX, terrainHeight(camX, camZ) + 6.0, camZ}, {-12.0, -1.0, 0.0}, 0.9, 0.05, 100.0);
    return s;
}

Scene stainedGlass() {
    Scene s;
    s.name = "stained-glass";
    s.textures.push_back(stainedGlassTexture());
    const int wallMat = addMaterial(s, "walls", {0.7f, 0.7f, 0.7f});
    const int woodMat = addMaterial(s, "wood", {0.55f, 0.4f, 0.28f});

    MeshBuilder room("room", wallMat);
    room.box({0, 2.25, 0}, {5, 2.25, 5}, 0.0, true);
    addMesh(s, room);
    MeshBuilder furniture("furniture", woodMat);
    furniture.box({1.0, 0.75, 1.2}, {0.8, 0.05, 0.5}, 0.3);  // table top
    for (double dx : {-0.7, 0.7}) {
        for (double dz : {-0.4, 0.4}) furniture.box({1.0 + dx * std::cos(0.3) + dz * std::sin(0.3), 0.35,
                                                     1.2 - dx * std::sin(0.3) + dz * std::cos(0.3)},
                                                    {0.05, 0.35, 0.05}, 0.3);
    }
    furniture.box({-1.5, 1.0, 2.5}, {0.25, 1.0, 0.25});  // pedestal
    addMesh(s, furniture);

    Light spot = spotLight("window", {-4.2, 4.2, -4.2}, {1.0, 0.0, 1.0}, 600.0, {1.0, 0.97, 0.9}, 0.3, 0.42);
    spot.cookie = 0;
    s.lights.push_back(spot);
    s.medium = Medium{0.15, 0.01, 0.2};
    s.camera = lookAt("side", {4.2, 1.6, -4.0}, {-1.0, 1.8, -0.5}, 1.0, 0.05, 30.0);
    return s;
}

Scene tvRoom() {
    Scene s;
    s.name = "tv-room";
    s.textures.push_back(tvTexture());
    const int wallMat = addMaterial(s, "walls", {0.6f, 0.6f, 0.6f});
    const int fabricMat = addMaterial(s, "sofa", {0.55f, 0.2f, 0.15f});
    const int darkMat = addMaterial(s, "tv_body", {0.05f, 0.05f, 0.05f});
    Material screen;
    screen.name = "tv_screen";
    screen.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    screen.emissiveFactor = glm::vec3(1.0f);
    screen.emissiveStrength = 12.0f;
    screen.emissiveTexture = 0;
    s.materials.push_back(screen);
    const int screenMat = int(s.materials.size() - 1);

    MeshBuilder room("room", wallMat);
    room.box({0, 1.4, 0}, {3, 1.4, 3}, 0.0, true);
    addMesh(s, room);

    // Sofa facing the TV (seat, back, arms) and a coffee table between them.
    MeshBuilder sofa("sofa", fabricMat);
    sofa.box({0, 0.25, 0.2}, {1.1, 0.25, 0.45});
    sofa.box({0, 0.75, 0.55}, {1.1, 0.5, 0.12});
    for (double x : {-1.15, 1.15}) sofa.box({x, 0.4, 0.2}, {0.12, 0.4, 0.45});
    sofa.box({0, 0.42, -1.3}, {0.6, 0.03, 0.35});
    for (double x : {-0.5, 0.5}) {
        for (double z : {-1.55, -1.05}) sofa.box({x, 0.2, z}, {0.03, 0.2, 0.03});
    }
    addMesh(s, sofa);

    MeshBuilder body("tv_body", darkMat);
    body.box({0, 1.3, -2.96}, {0.85, 0.5, 0.04});
    addMesh(s, body);

    // Screen 1.6 x 0.9 m at z = -2.9, facing +z (counter-clockwise seen from +z); uv (0,0) at the
    // top-left corner as seen from the room, v growing downwards (glTF's image convention).
    MeshBuilder tv("tv_screen", screenMat);
    Mesh& m = tv.mesh();
    m.positions = {{-0.8f, 1.75f, -2.9f}, {0.8f, 1.75f, -2.9f}, {-0.8f, 0.85f, -2.9f}, {0.8f, 0.85f, -2.9f}};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    m.indices = {2, 3, 1, 2, 1, 0};
    addMesh(s, tv);
    s.lights.push_back(areaLightFromMesh(s, int(s.meshes.size() - 1)));

    s.medium = Medium{0.3, 0.02, 0.3};
    s.camera = lookAt("side", {2.6, 1.5, 2.2}, {-0.9, 0.9, -1.6}, 0.9, 0.05, 20.0);
    return s;
}

}  // namespace

std::vector<std::string> builtinSceneNames() {
    return {"colonnade", "grate", "forest", "terrain", "stained-glass", "tv-room"};
}

std::string defaultSceneName() { return "colonnade"; }

bool isBuiltinScene(const std::string& name) {
    const auto names = builtinSceneNames();
    return std::find(names.begin(), names.end(), name) != names.end();
}

Scene makeBuiltinScene(const std::string& name) {
    if (name == "colonnade") return colonnade();
    if (name == "grate") return grate(1.0);
    if (name == "forest") return forest(1.0);
    if (name == "terrain") return terrain(1.0);
    if (name == "stained-glass") return stainedGlass();
    if (name == "tv-room") return tvRoom();
    std::string known;
    for (const std::string& n : builtinSceneNames()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("unknown built-in scene '" + name + "' (known: " + known + ")");
}

std::vector<std::string> detailedSceneNames() { return {"grate", "forest", "terrain"}; }

Scene makeDetailedScene(const std::string& name, double detail) {
    if (!(detail >= kMinSceneDetail && detail <= kMaxSceneDetail))
        throw InputError("scene detail " + std::to_string(detail) + " is outside [" + std::to_string(kMinSceneDetail) +
                         ", " + std::to_string(kMaxSceneDetail) + "]");
    if (name == "grate") return grate(detail);
    if (name == "forest") return forest(detail);
    if (name == "terrain") return terrain(detail);
    makeBuiltinScene(name);  // an unknown name fails there, listing the known ones
    throw InputError("scene '" + name + "' has no detail parameter (grate, forest and terrain have: more bars, "
                     "trees or heightfield samples)");
}

Scene makeTestScene() {
    Scene s;
    s.name = "test";
    const int floorMat = addMaterial(s, "floor", {0.5f, 0.5f, 0.5f});
    const int boxMat = addMaterial(s, "box", {0.8f, 0.2f, 0.2f});
    MeshBuilder floor("floor", floorMat);
    floor.quad({-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2});
    addMesh(s, floor);
    MeshBuilder box("box", boxMat);
    box.box({0, 1.5, 0}, {0.4, 0.1, 0.4});
    addMesh(s, box);
    s.lights.push_back(spotLight("spot", {0, 3, 0}, {0, 0, 0}, 50.0, {1, 1, 1}, 0.3, 0.5));
    s.medium = Medium{0.2, 0.02, 0.3};
    s.camera = lookAt("camera", {0, 1.2, 4}, {0, 1, 0}, 0.9, 0.05, 20.0);
    return s;
}

Scene makeTestAreaLightScene() {
    Scene s;
    s.name = "test-area";
    Texture t = makeTexture("emission", 4, 4);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) setTexel(t, x, y, {x / 3.0, y / 3.0, 1.0});
    }
    s.textures.push_back(t);
    const int floorMat = addMaterial(s, "floor", {0.5f, 0.5f, 0.5f});
    Material emitter;
    emitter.name = "emitter";
    emitter.emissiveFactor = glm::vec3(1.0f, 0.9f, 0.8f);
    emitter.emissiveStrength = 5.0f;
    emitter.emissiveTexture = 0;
    s.materials.push_back(emitter);
    MeshBuilder floor("floor", floorMat);
    floor.quad({-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2});
    addMesh(s, floor);
    // Facing down (-Y): counter-clockwise seen from below.
    MeshBuilder panel("panel", int(s.materials.size() - 1));
    panel.quad({-0.5, 2, -0.5}, {0.5, 2, -0.5}, {0.5, 2, 0.5}, {-0.5, 2, 0.5});
    addMesh(s, panel);
    s.lights.push_back(areaLightFromMesh(s, 1));
    s.medium = Medium{0.2, 0.0, 0.0};
    s.camera = lookAt("camera", {0, 1.0, 4}, {0, 1, 0}, 0.9, 0.05, 20.0);
    return s;
}

}  // namespace viz::scene
