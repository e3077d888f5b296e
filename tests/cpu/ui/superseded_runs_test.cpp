// A CPU run superseded while its pass is running (the camera moved under the reference): the pass still
// finishes, and its result must not be taken for the request that superseded it. A gated fake technique
// lets the test hold each pass until the next request is in; its image is the camera's x, so every image
// names the request it was rendered for.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>

#include "cpu/ui/gated_technique.h"
#include "difference_runs.h"

namespace airlight {
namespace {

using namespace airlight::testing;

// Waits (up to 20 s) for the worker's next accepted result.
std::optional<std::string> polled(DifferenceRuns& runs) {
    std::optional<std::string> done;
    for (auto start = std::chrono::steady_clock::now(); !done && std::chrono::steady_clock::now() - start < 20s;) {
        done = runs.poll();
        std::this_thread::sleep_for(1ms);
    }
    return done;
}

TEST(SupersededRuns, EveryResultCarriesTheTicketOfTheRequestItAnswers) {
    auto gate = std::make_shared<Gate>();
    viz::scene::Scene scene;
    CpuWorker worker(scene, gatedMaker(gate));
    EXPECT_FALSE(worker.progress().busy);
    const std::uint64_t first = worker.submit({"gated", cameraAt(1.0), {}, 4, 3});
    EXPECT_TRUE(worker.progress().busy) << "a request not yet taken by the thread is work to wait for";
    ASSERT_TRUE(gate->waitEntered(1));
    const std::uint64_t second = worker.submit({"gated", cameraAt(2.0), {}, 4, 3});
    EXPECT_GT(second, first);
    gate->release();  // the first request's pass finishes after the second came in

    const std::optional<CpuResult> a = nextResult(worker);
    ASSERT_TRUE(a);
    EXPECT_EQ(a->ticket, first);
    EXPECT_EQ(a->output.airlight.pixels.front(), 1.0f);
    ASSERT_TRUE(gate->waitEntered(2));
    EXPECT_TRUE(worker.progress().busy);
    gate->release();
    const std::optional<CpuResult> b = nextResult(worker);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->ticket, second);
    EXPECT_EQ(b->output.airlight.pixels.front(), 2.0f);
}

TEST(SupersededRuns, ADifferenceViewNeverKeepsASupersededPassUnderTheNewRequest) {
    auto gate = std::make_shared<Gate>();
    RunPool pool(gatedMaker(gate));
    DifferenceRuns runs(pool);
    viz::scene::Scene scene;
    DifferenceRequest request{&scene, cameraAt(1.0), {4, 3}, {}};
    EXPECT_EQ(runs.get("gated", request), nullptr);  // started
    ASSERT_TRUE(gate->waitEntered(1));
    request.camera = cameraAt(2.0);  // the camera moves while the first pass runs
    EXPECT_EQ(runs.get("gated", request), nullptr);
    gate->release();
    // The first pass has finished once the second one has started.
    ASSERT_TRUE(gate->waitEntered(2));
    EXPECT_EQ(runs.poll(), std::nullopt) << "the superseded pass was taken for the new request";
    EXPECT_TRUE(runs.pending());
    EXPECT_EQ(runs.get("gated", request), nullptr) << "still computing";
    gate->release();
    ASSERT_EQ(polled(runs), std::optional<std::string>("gated"));
    const DifferenceRuns::Run* run = runs.get("gated", request);
    ASSERT_NE(run, nullptr);
    EXPECT_EQ(run->airlight.pixels.front(), 2.0f) << "the image is of the camera asked for";
    EXPECT_FALSE(runs.pending());
}

TEST(SupersededRuns, WhilePlayingACpuTechniquesLastImageStandsInsteadOfARequestPerFrame) {
    auto gate = std::make_shared<Gate>();
    RunPool pool(gatedMaker(gate));
    DifferenceRuns runs(pool);
    viz::scene::Scene scene;
    DifferenceRequest request{&scene, cameraAt(1.0), {4, 3}, {}, true};
    EXPECT_EQ(runs.get("gated", request), nullptr);  // nothing yet: the first request starts
    ASSERT_TRUE(gate->waitEntered(1));
    for (int frame = 2; frame <= 5; ++frame) {  // the light moves every played frame
        request.camera = cameraAt(frame);
        EXPECT_EQ(runs.get("gated", request), nullptr) << "no image yet, and the pass under way is not superseded";
    }
    gate->release();
    ASSERT_EQ(polled(runs), std::optional<std::string>("gated"));
    EXPECT_FALSE(runs.pending()) << "automation would wait for ever while the animation plays";
    for (int frame = 6; frame <= 9; ++frame) {
        request.camera = cameraAt(frame);
        const DifferenceRuns::Run* run = runs.get("gated", request);
        ASSERT_NE(run, nullptr);
        EXPECT_TRUE(run->held);
        EXPECT_EQ(run->airlight.pixels.front(), 1.0f) << "the image of the request it was rendered for";
    }
    EXPECT_FALSE(runs.pending());
    {
        std::lock_guard lock(gate->mutex);
        EXPECT_EQ(gate->entered, 1) << "a played frame started a pass";
    }
    request.hold = false;  // play stops: the frame as it is now
    EXPECT_EQ(runs.get("gated", request), nullptr);
    ASSERT_TRUE(gate->waitEntered(2));
    gate->release();
    ASSERT_EQ(polled(runs), std::optional<std::string>("gated"));
    const DifferenceRuns::Run* run = runs.get("gated", request);
    ASSERT_NE(run, nullptr);
    EXPECT_FALSE(run->held);
    EXPECT_EQ(run->airlight.pixels.front(), 9.0f);
}

}  // namespace
}  // namespace airlight
