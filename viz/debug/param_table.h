// Typed settings: a technique declares each of its parameters once, as a field of its own settings struct
// together with the parameter's name, help, default and range (ParamInfo), in the spirit of property
// reflection. params() lists the declarations; read() fills the struct from a run's complete Settings, once,
// at the start of the run, so the technique's code reads fields instead of looking names up.
//
//     struct MarchSettings { int samples = 0; bool exact = false; };
//     const ParamTable<MarchSettings> kTable = ParamTable<MarchSettings>()
//         .add(&MarchSettings::samples, {"samples", "samples per pixel", 64, 1, 65536, true})
//         .add(&MarchSettings::exact, {"exact", "1: exact per interval", 0, 0, 1, true});
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "debug/params.h"

namespace viz {

// A setting's value (Settings hold doubles) as a field of type T: a bool is "not 0", an enum is its
// integer value, any other number converts as a cast would.
template <class T>
T settingAs(double value) {
    if constexpr (std::is_same_v<T, bool>) {
        return value != 0.0;
    } else if constexpr (std::is_enum_v<T>) {
        return T(int(value));
    } else {
        return T(value);
    }
}

template <class S>
class ParamTable {
public:
    // A parameter stored in `field`.
    template <class T>
    ParamTable add(T S::*field, ParamInfo info) && {
        mInfos.push_back(std::move(info));
        mSetters.push_back([field](S& s, double value) { s.*field = settingAs<T>(value); });
        return std::move(*this);
    }
    // Parameters declared elsewhere (the shared passes' shadow_map, area_samples) stored in fields here.
    template <class T>
    ParamTable add(T S::*field, const std::vector<ParamInfo>& infos, const std::string& name) && {
        const ParamInfo* info = named(infos, name);
        return info ? std::move(*this).add(field, *info) : std::move(*this);
    }

    // A parameter the technique declares but does not store here: the controls (pick, orbit, clock), which
    // a run reads from FrameInput::controls, and names shared code reads from the Settings (the shared
    // passes' shadow_map, substepLimit's sub-step parameter). Listed, so --set and lessons accept them.
    ParamTable declare(ParamInfo info) && {
        mInfos.push_back(std::move(info));
        mSetters.push_back(nullptr);
        return std::move(*this);
    }
    // The one named `name` from a shared list.
    ParamTable declare(const std::vector<ParamInfo>& infos, const std::string& name) && {
        const ParamInfo* info = named(infos, name);
        return info ? std::move(*this).declare(*info) : std::move(*this);
    }
    // Several of them (the shared passes' list).
    ParamTable declare(std::vector<ParamInfo> infos) && {
        for (ParamInfo& info : infos) *this = std::move(*this).declare(std::move(info));
        return std::move(*this);
    }

    const std::vector<ParamInfo>& infos() const { return mInfos; }
    // Names given to add() above that the shared list did not have (empty in a correct declaration).
    const std::vector<std::string>& missing() const { return mMissing; }

    // The struct of a run's settings; `settings` must hold every declared name (FrameInput::settings are
    // complete).
    S read(const Settings& settings) const {
        S s{};
        for (std::size_t i = 0; i < mInfos.size(); ++i)
            if (mSetters[i]) mSetters[i](s, settings.at(mInfos[i].name));
        return s;
    }
    // The same from settings that may leave names out: those take their declared default (for a technique
    // whose callers pass partial settings, as the reference's do).
    S readWithDefaults(const Settings& settings) const {
        S s{};
        for (std::size_t i = 0; i < mInfos.size(); ++i) {
            if (!mSetters[i]) continue;
            const auto it = settings.find(mInfos[i].name);
            mSetters[i](s, it == settings.end() ? mInfos[i].defaultValue : it->second);
        }
        return s;
    }

private:
    // `name` in `infos`; null, and noted in missing(), when the list lacks it.
    const ParamInfo* named(const std::vector<ParamInfo>& infos, const std::string& name) {
        for (const ParamInfo& info : infos)
            if (info.name == name) return &info;
        mMissing.push_back(name);
        return nullptr;
    }

    std::vector<ParamInfo> mInfos;
    std::vector<std::function<void(S&, double)>> mSetters;
    std::vector<std::string> mMissing;
};

}  // namespace viz
