// A technique whose card is data. Its id, one-line description, the run request's fields it reads
// (Controls) and whether it needs GL are given once, to the constructor; its parameters are its settings
// struct's ParamTable (debug/param_table.h); its stages are the list its constructor declares in mStages.
// The six accessors every technique would otherwise write out are answered here, the same way for all.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "debug/param_table.h"
#include "debug/technique.h"

namespace viz {

struct TechniqueCard {
    std::string id;           // stable: the command line, lessons and tests name the technique by it
    std::string description;  // one line
    Controls controls{};
    bool needsGl = true;
};

template <class SettingsT>
class DeclaredTechnique : public Technique {
public:
    std::string id() const final { return mCard.id; }
    std::string description() const final { return mCard.description; }
    const std::vector<StageInfo>& stages() const final { return mStages; }
    const std::vector<ParamInfo>& params() const final { return mTable.infos(); }
    Controls controls() const final { return mCard.controls; }
    bool needsGl() const final { return mCard.needsGl; }

protected:
    DeclaredTechnique(TechniqueCard card, const ParamTable<SettingsT>& table) : mCard(std::move(card)), mTable(table) {}
    // Settings as this technique's struct (every name present: a run's settings are complete).
    SettingsT read(const Settings& settings) const { return mTable.read(settings); }

    std::vector<StageInfo> mStages;  // declared by the constructor, in run order

private:
    TechniqueCard mCard;
    const ParamTable<SettingsT>& mTable;  // a function-local static of the technique's files
};

}  // namespace viz
