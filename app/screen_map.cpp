#include "screen_map.h"

#include <utility>

namespace airlight {

void ScreenMap::clear() {
    mNamed.clear();
    mViews.clear();
}

void ScreenMap::place(const std::string& name, const Rect& rect, bool keepFirst) {
    if (keepFirst) mNamed.emplace(name, rect);
    else mNamed[name] = rect;
}

void ScreenMap::placeView(View view) { mViews.push_back(std::move(view)); }

std::optional<ScreenMap::Rect> ScreenMap::find(const std::string& name, const std::map<std::string, Rect>& widgets) const {
    if (const auto it = widgets.find(name); it != widgets.end()) return it->second;
    for (const View& v : mViews)
        if (v.name == name) return v.rect;
    if (const auto it = mNamed.find(name); it != mNamed.end()) return it->second;
    return std::nullopt;
}

std::string ScreenMap::known(const std::map<std::string, Rect>& widgets) const {
    std::string known;
    const auto add = [&](const std::string& name) { known += (known.empty() ? "" : ", ") + name; };
    for (const auto& [name, r] : mNamed) add(name);
    for (const View& v : mViews) add(v.name);
    for (const auto& [name, r] : widgets) add(name);
    return known;
}

}  // namespace airlight
