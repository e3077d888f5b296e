// The window's technique instances (app/run_pool.h): one per consumer and technique, made once, an
// unknown technique refused without leaving anything behind.
#include <gtest/gtest.h>

#include <stdexcept>

#include "run_pool.h"
#include "techniques/registry.h"

namespace airlight {
namespace {

TEST(RunPool, EachConsumerHasItsOwnInstanceMadeOnce) {
    int made = 0;
    RunPool pool([&made](const std::string& id) {
        ++made;
        return viz::makeTechnique(id);
    });
    RunScheduler& views = pool.runner(Consumer::Views, "reference");
    EXPECT_EQ(&pool.runner(Consumer::Views, "reference"), &views) << "asked again: the same instance";
    RunScheduler& others = pool.runner(Consumer::Others, "reference");
    EXPECT_NE(&others, &views) << "a difference view's run would replace what the main views borrow";
    EXPECT_NE(&others.technique(), &views.technique());
    EXPECT_EQ(made, 2);
    EXPECT_EQ(&pool.at(Consumer::Views, "reference"), &views);
    EXPECT_EQ(views.technique().id(), "reference");
    pool.clear();
    EXPECT_THROW((void)pool.at(Consumer::Views, "reference"), std::out_of_range);
}

TEST(RunPool, AnUnknownTechniqueIsRefusedAndNothingIsStored) {
    RunPool pool;
    EXPECT_ANY_THROW((void)pool.runner(Consumer::Others, "no-such-technique"));
    EXPECT_THROW((void)pool.at(Consumer::Others, "no-such-technique"), std::out_of_range);
    EXPECT_EQ(pool.runner(Consumer::Others, "raymarch").technique().id(), "raymarch");
}

}  // namespace
}  // namespace airlight
