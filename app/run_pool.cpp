#include "run_pool.h"

namespace airlight {

RunScheduler& RunPool::runner(Consumer who, const std::string& id) {
    auto it = mRunners.find({who, id});
    if (it == mRunners.end()) {
        // makeTechnique throws for an unknown id before anything is stored.
        auto technique = mMake ? mMake(id) : viz::makeTechnique(id);
        it = mRunners.emplace(std::pair{who, id}, std::make_unique<RunScheduler>(std::move(technique))).first;
        if (who == Consumer::Views) it->second->setTimer(mViewsTimer);
    }
    return *it->second;
}

void RunPool::setViewsTimer(viz::StageTimer* timer) {
    mViewsTimer = timer;
    for (auto& [key, runner] : mRunners)
        if (key.first == Consumer::Views) runner->setTimer(timer);
}

CpuWorker& RunPool::worker(Worker who, const viz::scene::Scene& scene) {
    std::unique_ptr<CpuWorker>& w = mWorkers[who];
    if (!w) w = std::make_unique<CpuWorker>(scene, mMake);
    return *w;
}

CpuWorker& RunPool::freshWorker(Worker who, const viz::scene::Scene& scene) {
    mWorkers.erase(who);
    return worker(who, scene);
}

bool RunPool::cpuBusy() const {
    for (const auto& [who, w] : mWorkers)
        if (w->progress().busy) return true;
    return false;
}

}  // namespace airlight
