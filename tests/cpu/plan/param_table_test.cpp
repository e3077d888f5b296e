// Typed settings (debug/param_table.h): a parameter declared once as a field is listed with its
// declaration and read into its field with the conversion its type asks for; a declared-only parameter is
// listed and not stored; every technique's settings struct reads its own complete defaults.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "debug/param_table.h"
#include "techniques/registry.h"

namespace viz {
namespace {

enum class Mode { A = 0, B = 1, C = 2 };

struct Toy {
    int count = -1;
    double scale = -1.0;
    bool on = false;
    Mode mode = Mode::A;
    unsigned seed = 0;
};

ParamTable<Toy> toyTable() {
    return ParamTable<Toy>()
        .add(&Toy::count, {"count", "", 4, 1, 100, true})
        .add(&Toy::scale, {"scale", "", 0.5, 0, 1, false})
        .declare({"pick", "", 0, 0, 10, true})
        .add(&Toy::on, {"on", "", 0, 0, 1, true})
        .add(&Toy::mode, {"mode", "", 0, 0, 2, true, {"a", "b", "c"}})
        .add(&Toy::seed, {"seed", "", 1, 0, 1e9, true});
}

TEST(ParamTable, ListsEveryDeclarationInOrder) {
    const ParamTable<Toy> t = toyTable();
    std::vector<std::string> names;
    for (const ParamInfo& p : t.infos()) names.push_back(p.name);
    EXPECT_EQ(names, (std::vector<std::string>{"count", "scale", "pick", "on", "mode", "seed"}));
    EXPECT_EQ(t.infos()[4].choices.size(), 3u);
    EXPECT_TRUE(t.missing().empty());
}

TEST(ParamTable, ReadsEachFieldWithItsTypesConversion) {
    const Toy toy = toyTable().read({{"count", 7.0}, {"scale", 0.25}, {"pick", 3.0}, {"on", 1.0}, {"mode", 2.0},
                                     {"seed", 3000000000.0}});
    EXPECT_EQ(toy.count, 7);
    EXPECT_EQ(toy.scale, 0.25);
    EXPECT_TRUE(toy.on);
    EXPECT_EQ(toy.mode, Mode::C);
    EXPECT_EQ(toy.seed, 3000000000u) << "an unsigned field holds values past INT_MAX";
    // A bool is "not zero", as every technique read it before (value != 0.0).
    EXPECT_TRUE(toyTable().read({{"count", 1.0}, {"scale", 0.0}, {"pick", 0.0}, {"on", 2.0}, {"mode", 0.0},
                                 {"seed", 0.0}}).on);
}

TEST(ParamTable, ASharedNameTheListLacksIsReported) {
    const ParamTable<Toy> t = ParamTable<Toy>()
                                  .add(&Toy::count, std::vector<ParamInfo>{{"other", "", 0, 0, 1, true}}, "count")
                                  .declare(std::vector<ParamInfo>{}, "pick");
    EXPECT_EQ(t.missing(), (std::vector<std::string>{"count", "pick"}));
    EXPECT_TRUE(t.infos().empty());
}

TEST(ParamTable, PartialSettingsTakeTheDeclaredDefaults) {
    const Toy toy = toyTable().readWithDefaults({{"scale", 0.75}});
    EXPECT_EQ(toy.count, 4);
    EXPECT_EQ(toy.scale, 0.75);
    EXPECT_FALSE(toy.on);
    EXPECT_EQ(toy.seed, 1u);
}

TEST(ParamTable, ReadingSettingsWithoutADeclaredNameThrows) {
    // Runs get complete settings (completeSettings); a missing name is a programmer error, not a default.
    EXPECT_ANY_THROW(toyTable().read({{"count", 1.0}}));
}

// Every technique's parameters are declared once: names unique, each stage's parameters among them, and
// a run's complete default settings read without error (plan() reads them into the technique's struct).
TEST(ParamTable, EveryTechniqueDeclaresItsParametersOnce) {
    for (const std::string& id : techniqueIds()) {
        const auto t = makeTechnique(id);
        std::set<std::string> names;
        for (const ParamInfo& p : t->params()) EXPECT_TRUE(names.insert(p.name).second) << id << ": " << p.name;
        for (const StageInfo& st : t->stages())
            for (const std::string& name : st.params) EXPECT_TRUE(names.count(name)) << id << " " << st.id << ": " << name;
        const Settings defaults = completeSettings(*t, {});
        EXPECT_EQ(defaults.size(), names.size()) << id;
    }
}

// The window drives a technique's shared controls by asking controls(); a technique says it has one exactly
// when it declares that control's parameters, with the shared declaration's range.
TEST(ParamTable, ATechniquesControlsAreTheSharedParametersItDeclares) {
    const auto declares = [](const Technique& t, const ParamInfo& shared) {
        const ParamInfo* p = findParam(t, shared.name);
        if (!p) return false;
        EXPECT_EQ(p->minValue, shared.minValue) << t.id() << " " << shared.name;
        EXPECT_EQ(p->maxValue, shared.maxValue) << t.id() << " " << shared.name;
        EXPECT_EQ(p->defaultValue, shared.defaultValue) << t.id() << " " << shared.name;
        return true;
    };
    int picking = 0, orbiting = 0, animated = 0;
    for (const std::string& id : techniqueIds()) {
        const auto t = makeTechnique(id);
        const Controls c = t->controls();
        EXPECT_EQ(c.pickedPixel, declares(*t, pickParam('x', "")) && declares(*t, pickParam('y', ""))) << id;
        bool orbit = true;
        for (const ParamInfo& p : orbitParams("")) orbit = declares(*t, p) && orbit;
        EXPECT_EQ(c.orbitCamera, orbit) << id;
        EXPECT_EQ(c.animationTime, declares(*t, animationTimeParam(""))) << id;
        picking += c.pickedPixel;
        orbiting += c.orbitCamera;
        animated += c.animationTime;
    }
    // slices, minmax, vsv and ivsv follow a picked pixel; slices and polyvol have orbit views; slices scrolls
    // its noise with the clock.
    EXPECT_EQ(picking, 4);
    EXPECT_EQ(orbiting, 2);
    EXPECT_EQ(animated, 1);
}

}  // namespace
}  // namespace viz
