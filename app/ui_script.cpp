#include "ui_script.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace airlight {

namespace {

// Splits a line into words; "double quoted" words may hold spaces.
std::vector<std::string> words(const std::string& line, bool& unterminated) {
    std::vector<std::string> out;
    unterminated = false;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i >= line.size() || line[i] == '#') break;
        std::string word;
        if (line[i] == '"') {
            const std::size_t end = line.find('"', i + 1);
            if (end == std::string::npos) {
                unterminated = true;
                return out;
            }
            word = line.substr(i + 1, end - i - 1);
            i = end + 1;
        } else {
            while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) word += line[i++];
        }
        out.push_back(word);
    }
    return out;
}

bool parseFloat(const std::string& text, float& value) {
    std::istringstream in(text);
    in >> value;
    return in && in.eof() && std::isfinite(value);
}

}  // namespace

int scriptKeyCode(const std::string& name) {
    static const std::pair<const char*, int> kNamed[] = {
        {"Tab", GLFW_KEY_TAB},     {"Enter", GLFW_KEY_ENTER}, {"Escape", GLFW_KEY_ESCAPE}, {"Space", GLFW_KEY_SPACE},
        {"Left", GLFW_KEY_LEFT},   {"Right", GLFW_KEY_RIGHT}, {"Up", GLFW_KEY_UP},         {"Down", GLFW_KEY_DOWN},
        {"[", GLFW_KEY_LEFT_BRACKET}, {"]", GLFW_KEY_RIGHT_BRACKET}, {"PageUp", GLFW_KEY_PAGE_UP},
        {"PageDown", GLFW_KEY_PAGE_DOWN}, {",", GLFW_KEY_COMMA}, {".", GLFW_KEY_PERIOD}, {"Home", GLFW_KEY_HOME},
        {"End", GLFW_KEY_END}, {"=", GLFW_KEY_EQUAL}, {"-", GLFW_KEY_MINUS}};
    for (const auto& [n, code] : kNamed)
        if (name == n) return code;
    if (name.size() == 1 && std::isdigit(static_cast<unsigned char>(name[0]))) return GLFW_KEY_0 + (name[0] - '0');
    if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0])))
        return GLFW_KEY_A + (std::toupper(static_cast<unsigned char>(name[0])) - 'A');
    if (name.size() >= 2 && name[0] == 'F') {
        int n = 0;
        for (std::size_t i = 1; i < name.size(); ++i) {
            if (!std::isdigit(static_cast<unsigned char>(name[i]))) return -1;
            n = n * 10 + (name[i] - '0');
        }
        if (n >= 1 && n <= 12) return GLFW_KEY_F1 + n - 1;
    }
    return -1;
}

std::vector<ScriptAction> parseScript(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw viz::InputError("cannot read script '" + path + "'");
    std::vector<ScriptAction> actions;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const auto fail = [&](const std::string& why) {
            throw viz::InputError(path + ":" + std::to_string(number) + ": " + why);
        };
        bool unterminated = false;
        const std::vector<std::string> w = words(line, unterminated);
        if (unterminated) fail("a quoted name is not closed");
        if (w.empty()) continue;
        ScriptAction a;
        a.line = number;
        if (w[0] == "click" || w[0] == "hover") {
            if (w.size() != 2 && w.size() != 4) fail(w[0] + " takes a name and optionally two fractions FX FY");
            a.kind = w[0] == "click" ? ScriptAction::Kind::Click : ScriptAction::Kind::Hover;
            a.target = w[1];
            if (w.size() == 4 && (!parseFloat(w[2], a.fraction.x) || !parseFloat(w[3], a.fraction.y) ||
                                  a.fraction.x < 0.0f || a.fraction.x > 1.0f || a.fraction.y < 0.0f || a.fraction.y > 1.0f))
                fail(w[0] + " fractions must be numbers from 0 to 1");
        } else if (w[0] == "drag") {
            if (w.size() != 6 && w.size() != 7) fail("drag takes a name, four fractions FX FY TX TY and optionally ONTO");
            a.kind = ScriptAction::Kind::Drag;
            a.target = w[1];
            float f[4];
            for (int i = 0; i < 4; ++i)
                if (!parseFloat(w[std::size_t(2 + i)], f[i]) || f[i] < 0.0f || f[i] > 1.0f)
                    fail("drag fractions must be numbers from 0 to 1");
            a.fraction = {f[0], f[1]};
            a.to = {f[2], f[3]};
            if (w.size() == 7) a.onto = w[6];
        } else if (w[0] == "key" || w[0] == "hold") {
            const bool hold = w[0] == "hold";
            if (!hold && w.size() != 2) fail("key takes one key name");
            if (hold) {
                float n = 0.0f;
                if (w.size() != 3 || !parseFloat(w[2], n) || n < 1.0f || n > 100000.0f || n != std::floor(n))
                    fail("hold takes a key name and a whole number of frames from 1 to 100000");
                a.frames = int(n);
            }
            std::string name = w[1];
            for (bool more = true; more;) {
                more = false;
                for (const auto& [prefix, mod] : {std::pair<const char*, int>{"Shift+", GLFW_MOD_SHIFT},
                                                  std::pair<const char*, int>{"Ctrl+", GLFW_MOD_CONTROL}})
                    if (name.size() > std::string(prefix).size() && name.rfind(prefix, 0) == 0) {
                        a.modifiers |= mod;
                        name = name.substr(std::string(prefix).size());
                        more = true;
                    }
            }
            if (scriptKeyCode(name) < 0) fail("unknown key '" + w[1] + "'");
            a.kind = hold ? ScriptAction::Kind::Hold : ScriptAction::Kind::Key;
            a.target = name;
        } else if (w[0] == "wheel") {
            float n = 0.0f;
            if (w.size() != 3 || !parseFloat(w[2], n) || n == 0.0f || std::abs(n) > 100.0f)
                fail("wheel takes a name and a number of notches from -100 to 100 (not 0)");
            a.kind = ScriptAction::Kind::Wheel;
            a.target = w[1];
            a.notches = n;
        } else if (w[0] == "frames") {
            float n = 0.0f;
            if (w.size() != 2 || !parseFloat(w[1], n) || n < 1.0f || n > 100000.0f || n != std::floor(n))
                fail("frames takes a whole number from 1 to 100000");
            a.kind = ScriptAction::Kind::Frames;
            a.frames = int(n);
        } else if (w[0] == "type" || w[0] == "drop") {
            if (w.size() != 2 || w[1].empty()) fail(w[0] + " takes one argument (quote it when it has spaces)");
            a.kind = w[0] == "type" ? ScriptAction::Kind::Type : ScriptAction::Kind::Drop;
            a.target = w[1];
        } else if (w[0] == "screenshot" || w[0] == "sidecar") {
            if (w.size() != 2) fail(w[0] + " takes one path");
            a.kind = w[0] == "screenshot" ? ScriptAction::Kind::Screenshot : ScriptAction::Kind::Sidecar;
            a.target = w[1];
        } else if (w[0] == "stats") {
            if (w.size() != 2) fail("stats takes one path");
            a.kind = ScriptAction::Kind::Stats;
            a.target = w[1];
        } else {
            fail("unknown action '" + w[0] + "' (known: click, hover, drag, wheel, key, hold, type, drop, frames, screenshot, sidecar, stats)");
        }
        actions.push_back(std::move(a));
    }
    return actions;
}

}  // namespace airlight
