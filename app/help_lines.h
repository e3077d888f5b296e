// The help at the bottom of the window: the key table's briefs (input_table.h) packed into whole lines
// that fit the window's width, so that a narrow window shows every key on more lines instead of cutting
// the last ones off.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace airlight {

// Packs `briefs` (input_table.h's helpBriefs, and the window's own facts), in order and never cut, into
// lines no wider than `width` by `measure`, three spaces between two briefs on a line; a brief wider
// than `width` gets a line of its own. At most `maxLines` lines: the last takes whatever is left (and
// is clipped when drawn).
std::vector<std::string> packHelp(const std::vector<std::string>& briefs, float width,
                                  const std::function<float(std::string_view)>& measure, int maxLines);

}  // namespace airlight
