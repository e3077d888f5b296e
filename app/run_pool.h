// The window's runs: every consumer gets its scheduler (run_scheduler.h) and its CPU worker (cpu_worker.h)
// here, made on first use, so technique instances and worker threads are made, timed and dropped in one
// place.
//
// Two consumers: the main views (Consumer::Views), whose panes borrow the textures a run publishes, and
// the others (Consumer::Others: the difference views and the comparison grid), which copy their images
// out of each run. A technique has one instance per consumer, never shared between them, so a difference
// view's run cannot replace a texture the main views are drawing (tests/cpu/ui/run_pool_test.cpp).
//
// CPU techniques (the reference) run on worker threads, one per consumer of CPU runs (Worker): a worker
// runs one request at a time and a new one supersedes it, so the difference views' requests must not
// supersede the main views', nor the comparison grid's reference either of theirs.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>

#include "cpu_worker.h"
#include "run_scheduler.h"
#include "scene/scene.h"
#include "techniques/registry.h"

namespace airlight {

enum class Consumer { Views, Others };
enum class Worker { Views, Differences, Comparison };

class RunPool {
public:
    // `make`: what makes a technique (the registry's when null; tests pass their own).
    explicit RunPool(viz::TechniqueMaker make = nullptr) : mMake(std::move(make)) {}

    // `id`'s scheduler for `who`, made on first use. An unknown id throws (InputError), storing nothing.
    RunScheduler& runner(Consumer who, const std::string& id);
    // The one `runner` made (std::out_of_range when it was not).
    const RunScheduler& at(Consumer who, const std::string& id) const { return *mRunners.at({who, id}); }
    // The clock the main views' GPU runs are timed by (null: each technique's own), for their schedulers
    // made and to be made.
    void setViewsTimer(viz::StageTimer* timer);
    // Drops every instance (the window closes: after the panes that borrow their textures).
    void clear() { mRunners.clear(); }

    // `who`'s CPU worker, made on first use with its own copy of `scene` (a later call hands it nothing:
    // the consumer calls setScene when its scene changes, as it knows when that is).
    CpuWorker& worker(Worker who, const viz::scene::Scene& scene);
    // A new worker for `who` in place of its last one, which drops its request; a pass it is running
    // finishes on its own and its result is lost with it (the comparison grid's reference starts afresh
    // on every open, so no pass of an older grid can arrive).
    CpuWorker& freshWorker(Worker who, const viz::scene::Scene& scene);
    void dropWorker(Worker who) { mWorkers.erase(who); }
    // Whether any worker has a pass running or a request waiting.
    bool cpuBusy() const;

private:
    viz::TechniqueMaker mMake;
    viz::StageTimer* mViewsTimer = nullptr;
    std::map<std::pair<Consumer, std::string>, std::unique_ptr<RunScheduler>> mRunners;
    std::map<Worker, std::unique_ptr<CpuWorker>> mWorkers;
};

}  // namespace airlight
