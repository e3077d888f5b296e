// The window's technique instances and CPU workers (app/run_pool.h): one instance per consumer and
// technique, made once, an unknown technique refused without leaving anything behind; one worker thread
// per consumer of CPU runs, so that one's request never supersedes another's.
#include <gtest/gtest.h>

#include <stdexcept>

#include "cpu/ui/gated_technique.h"
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

TEST(RunPool, EachConsumerOfCpuRunsHasItsOwnWorkerSoNoneSupersedesAnother) {
    using namespace airlight::testing;
    auto gate = std::make_shared<Gate>();
    RunPool pool(gatedMaker(gate));
    const viz::scene::Scene scene;
    CpuWorker& views = pool.worker(Worker::Views, scene);
    EXPECT_EQ(&pool.worker(Worker::Views, scene), &views) << "asked again: the same thread";
    CpuWorker& differences = pool.worker(Worker::Differences, scene);
    ASSERT_NE(&differences, &views);
    EXPECT_FALSE(pool.cpuBusy());
    const std::uint64_t a = views.submit({"gated", cameraAt(1.0), {}, 4, 3});
    EXPECT_TRUE(pool.cpuBusy());
    const std::uint64_t b = differences.submit({"gated", cameraAt(2.0), {}, 4, 3});
    // Both passes run at once: the second request went to another thread instead of superseding the first.
    ASSERT_TRUE(gate->waitEntered(2));
    gate->release();
    gate->release();
    const std::optional<CpuResult> ra = nextResult(views), rb = nextResult(differences);
    ASSERT_TRUE(ra && rb);
    EXPECT_EQ(ra->ticket, a);
    EXPECT_EQ(ra->output.airlight.pixels.front(), 1.0f);
    EXPECT_EQ(rb->ticket, b);
    EXPECT_EQ(rb->output.airlight.pixels.front(), 2.0f);
    // Each pass of the worker's request arrives; let any later ones through.
    for (int k = 0; k < 8; ++k) gate->release();
    // The comparison grid's reference starts on a new thread on every open.
    CpuWorker* first = &pool.freshWorker(Worker::Comparison, scene);
    EXPECT_EQ(first->submit({"gated", cameraAt(3.0), {}, 4, 3}), 1u) << "a new worker's first ticket";
    CpuWorker* second = &pool.freshWorker(Worker::Comparison, scene);
    EXPECT_EQ(second->submit({"gated", cameraAt(4.0), {}, 4, 3}), 1u) << "not the last grid's worker";
    for (int k = 0; k < 16; ++k) gate->release();
    pool.dropWorker(Worker::Comparison);
}

}  // namespace
}  // namespace airlight
