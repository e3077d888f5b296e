// The window's technique instances: every consumer of runs gets its scheduler (run_scheduler.h) here, made
// on first use, so instances are made, timed and dropped in one place.
//
// Two consumers: the main views (Consumer::Views), whose panes borrow the textures a run publishes, and
// the others (Consumer::Others: the difference views and the comparison grid), which copy their images
// out of each run. A technique has one instance per consumer, never shared between them, so a difference
// view's run cannot replace a texture the main views are drawing (tests/cpu/ui/run_pool_test.cpp).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>

#include "run_scheduler.h"
#include "techniques/registry.h"

namespace airlight {

enum class Consumer { Views, Others };

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

private:
    viz::TechniqueMaker mMake;
    viz::StageTimer* mViewsTimer = nullptr;
    std::map<std::pair<Consumer, std::string>, std::unique_ptr<RunScheduler>> mRunners;
};

}  // namespace airlight
