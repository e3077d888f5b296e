// The window's key table (app/input_table.h): the README's copy is the generated one, every key the
// window documents does what its row says in each context, and no key means two things at once.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "input_table.h"

namespace airlight {
namespace {

std::string readmeKeyTable() {
    std::ifstream in(std::string(VIZ_SOURCE_DIR) + "/README.md");
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    const std::string begin = "<!-- keys:begin", end = "<!-- keys:end -->";
    const auto b = s.find(begin), e = s.find(end);
    if (b == std::string::npos || e == std::string::npos || e < b) return "(README.md has no keys:begin / keys:end markers)";
    const auto first = s.find('\n', b) + 1;
    return s.substr(first, e - first);
}

TEST(InputTable, TheReadmeKeyTableIsTheGeneratedOne) {
    EXPECT_EQ(readmeKeyTable(), markdownKeyTable())
        << "README.md's key table (between the keys:begin and keys:end markers) must be, exactly:\n"
        << markdownKeyTable();
}

TEST(InputTable, InFlyModeTheMovementKeysOnlyDriveTheCamera) {
    const KeyState fly{true, false, false}, orbit{false, false, false};
    for (int key : {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E})
        for (bool shift : {false, true}) {
            EXPECT_EQ(commandForKey(key, shift, false, fly), Command::FlyMove) << key << " shift " << shift;
            EXPECT_EQ(commandForKey(key, shift, true, fly), Command::FlyMove) << key << " repeated";
        }
    EXPECT_EQ(commandForKey(GLFW_KEY_S, false, false, orbit), Command::NextStage);
    EXPECT_EQ(commandForKey(GLFW_KEY_S, true, false, orbit), Command::PrevStage);
    EXPECT_EQ(commandForKey(GLFW_KEY_D, true, true, orbit), Command::PrevSubstep);
    EXPECT_EQ(commandForKey(GLFW_KEY_E, false, false, orbit), Command::ExportView);
    EXPECT_EQ(commandForKey(GLFW_KEY_E, false, true, orbit), Command::None) << "a held E exports once";
    EXPECT_EQ(commandForKey(GLFW_KEY_C, false, false, fly), Command::ToggleCameraMode);
    EXPECT_EQ(commandForKey(GLFW_KEY_C, false, false, orbit), Command::ToggleCameraMode);
}

TEST(InputTable, RangesPairsAndTextFields) {
    const KeyState orbit{false, false, false};
    int offset = -1;
    EXPECT_EQ(commandForKey(GLFW_KEY_7, false, false, orbit, &offset), Command::PickTechnique);
    EXPECT_EQ(offset, 6);
    EXPECT_EQ(commandForKey(GLFW_KEY_LEFT_BRACKET, false, false, orbit), Command::PrevView);
    EXPECT_EQ(commandForKey(GLFW_KEY_RIGHT_BRACKET, true, false, orbit), Command::NextView);
    EXPECT_EQ(commandForKey(GLFW_KEY_V, true, false, orbit), Command::PrevView);
    EXPECT_EQ(commandForKey(GLFW_KEY_COMMA, false, false, orbit), Command::PrevLayer);
    EXPECT_EQ(commandForKey(GLFW_KEY_END, false, false, orbit), Command::LastSubstep);
    EXPECT_EQ(commandForKey(GLFW_KEY_F9, false, false, orbit), Command::LoadSession);
    const KeyState ctrl{false, false, false, true};
    EXPECT_EQ(commandForKey(GLFW_KEY_EQUAL, false, false, ctrl), Command::UiScaleUp);
    EXPECT_EQ(commandForKey(GLFW_KEY_MINUS, false, false, ctrl), Command::UiScaleDown);
    EXPECT_EQ(commandForKey(GLFW_KEY_S, false, false, ctrl), Command::None) << "Ctrl+S is not S";
    EXPECT_EQ(commandForChar('+'), Command::ExposureUp);
    EXPECT_EQ(commandForChar('-'), Command::ExposureDown);
    EXPECT_EQ(commandForChar(0x263a), Command::None);
    const KeyState text{false, false, true};
    for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key)
        EXPECT_EQ(commandForKey(key, false, false, text), Command::None) << "a text field takes key " << key;
    const KeyState lesson{false, true, false};
    EXPECT_EQ(commandForKey(GLFW_KEY_PAGE_DOWN, false, false, lesson), Command::LessonKey);
    EXPECT_EQ(commandForKey(GLFW_KEY_PAGE_DOWN, false, false, orbit), Command::None);
    EXPECT_EQ(commandForKey(GLFW_KEY_B, false, false, lesson), Command::LessonKey);
}

// Exhaustive over every GLFW key, both Shift states and every context: at most one row of the winning
// precedence claims a key, and every command the window performs is reachable from some key or character.
TEST(InputTable, NoKeyMeansTwoThingsAndEveryCommandHasAKey) {
    std::set<Command> reached;
    for (bool fly : {false, true})
        for (bool lesson : {false, true})
            for (bool ctrl : {false, true}) {
            const KeyState state{fly, lesson, false, ctrl};
            for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key)
                for (bool shift : {false, true}) {
                    std::map<int, int> claims;  // context rank -> rows claiming the key
                    for (const KeyBinding& b : keyBindings()) {
                        const bool mine = std::count(b.keys.begin(), b.keys.end(), key) +
                                              std::count(b.backKeys.begin(), b.backKeys.end(), key) > 0;
                        const bool applies = b.context == KeyContext::Any || (b.context == KeyContext::Fly && fly) ||
                                             (b.context == KeyContext::Orbit && !fly) ||
                                             (b.context == KeyContext::Lesson && lesson);
                        if (mine && applies && b.ctrl == ctrl) ++claims[b.context == KeyContext::Any ? 2 : b.context == KeyContext::Lesson ? 0 : 1];
                    }
                    for (const auto& [rank, n] : claims) EXPECT_LE(n, 1) << "key " << key << " rank " << rank;
                    reached.insert(commandForKey(key, shift, false, state));
                }
            }
    for (unsigned c = 0; c < 128; ++c) reached.insert(commandForChar(c));
    for (const KeyBinding& b : keyBindings()) {
        if (b.command == Command::Pointer || b.command == Command::None) continue;
        EXPECT_TRUE(reached.count(b.command)) << b.label << " is never reached";
        if (b.shifted != Command::None) {
            EXPECT_TRUE(reached.count(b.shifted)) << b.label << " (shifted) is never reached";
        }
    }
}

TEST(InputTable, HelpLinesFollowTheCameraMode) {
    const auto line = [](HelpLine l, bool fly) {
        std::string out;
        for (const std::string& b : helpBriefs(l, fly)) out += b + "   ";
        return out;
    };
    const std::string orbit = line(HelpLine::Frame, false), fly = line(HelpLine::Frame, true);
    EXPECT_NE(orbit.find("S/Shift+S stage"), std::string::npos) << orbit;
    EXPECT_EQ(fly.find("S/Shift+S stage"), std::string::npos) << fly;
    EXPECT_NE(fly.find("WASD move"), std::string::npos) << fly;
    EXPECT_EQ(orbit.find("WASD move"), std::string::npos) << orbit;
    EXPECT_NE(line(HelpLine::Views, false).find("H / J split"), std::string::npos);
    EXPECT_EQ(line(HelpLine::Views, true).find("E export"), std::string::npos) << "E belongs to the fly camera";
}

TEST(InputTable, KeyNamesAreTheKeysThatDoItWhereTheWindowIs) {
    const std::vector<Command> stepping = {Command::NextStage, Command::NextSubstep, Command::FirstSubstep,
                                           Command::LastSubstep};
    EXPECT_EQ(keyNames(stepping, KeyState{}), "S, D, Home, End");
    EXPECT_EQ(keyNames(stepping, KeyState{.fly = true}), "Home, End") << "S and D drive the fly camera";
    EXPECT_EQ(keyNames({Command::PrevStage, Command::PrevView, Command::PlayPause}, KeyState{}), "Shift+S, [, P");
    EXPECT_EQ(keyNames({Command::FlyMove}, KeyState{}), "") << "no key moves the orbit camera that way";
}

}  // namespace
}  // namespace airlight
