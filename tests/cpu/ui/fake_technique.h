// The part every fake CPU technique of the window's tests shares: an id and a description, its declared
// stages and parameters, no GL and no plan. A fake sets mStages and mParams and writes run().
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "debug/technique.h"

namespace airlight::testing {

class FakeTechnique : public viz::Technique {
public:
    FakeTechnique(std::string id, std::string description) : mId(std::move(id)), mDescription(std::move(description)) {}
    std::string id() const override { return mId; }
    std::string description() const override { return mDescription; }
    const std::vector<viz::StageInfo>& stages() const override { return mStages; }
    const std::vector<viz::ParamInfo>& params() const override { return mParams; }
    bool needsGl() const override { return false; }
    viz::Plan plan(const viz::scene::Scene&, const viz::Settings&) const override { return {}; }

protected:
    std::vector<viz::StageInfo> mStages;
    std::vector<viz::ParamInfo> mParams;

private:
    std::string mId, mDescription;
};

}  // namespace airlight::testing
