#include "cli_args.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "core/error.h"
#include "techniques/registry.h"

namespace airlight {

using viz::InputError;

std::string Args::next(const std::string& forFlag) {
    if (empty()) throw InputError("option " + forFlag + " needs a value");
    return take();
}

bool isHelpFlag(const std::string& word) { return word == "--help" || word == "-h" || word == "help"; }

double parseNumber(const std::string& text, const std::string& what) {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    // strtod skips leading blanks: a value with blanks on either side is refused alike. An overflow is
    // refused; an underflow (1e-320) is the tiny finite number strtod returns.
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])) || end != text.c_str() + text.size() ||
        !std::isfinite(v) || (errno == ERANGE && std::abs(v) > 1.0))
        throw InputError(what + ": '" + text + "' is not a finite number");
    return v;
}

int parseWholeNumber(const std::string& text, const std::string& flag, int lo, int hi) {
    const double v = parseNumber(text, flag);
    if (v < lo || v > hi || v != std::floor(v))
        throw InputError(flag + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                         ", not '" + text + "'");
    return int(v);
}

static int parseDimension(const std::string& text, const std::string& whole) {
    if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
        throw InputError("size '" + whole + "' must be WIDTHxHEIGHT, e.g. 160x120");
    return std::atoi(text.c_str());
}

glm::ivec2 parseSize(const std::string& text) {
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos) throw InputError("size '" + text + "' must be WIDTHxHEIGHT, e.g. 160x120");
    const int w = parseDimension(text.substr(0, x), text);
    const int h = parseDimension(text.substr(x + 1), text);
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
        throw InputError("size '" + text + "' is out of range: each side must be between 1 and " + std::to_string(kMaxImageSide));
    return {w, h};
}

void parseSetting(const std::string& text, viz::Settings& into, const std::string& technique) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError("--set expects name=value, got '" + text + "'");
    const std::string name = text.substr(0, eq);
    const std::string value = text.substr(eq + 1);
    // The technique whose parameter gives a word or an AxBxC value its meaning; when it has no parameter of
    // that name, the first technique that has one (the setting does not apply, and what uses it says so).
    std::vector<std::string> consulted = viz::techniqueIds();
    if (std::find(consulted.begin(), consulted.end(), technique) != consulted.end() &&
        viz::findParam(*viz::makeTechnique(technique), name))
        consulted = {technique};
    // AxBxC: one number per axis, for a parameter that declares its per-axis components.
    if (value.find('x') != std::string::npos && !value.empty() && std::isdigit(static_cast<unsigned char>(value[0]))) {
        std::vector<std::string> parts;
        for (std::size_t start = 0;;) {
            const std::size_t x = value.find('x', start);
            parts.push_back(value.substr(start, x == std::string::npos ? std::string::npos : x - start));
            if (x == std::string::npos) break;
            start = x + 1;
        }
        for (const std::string& id : consulted) {
            for (const viz::ParamInfo& p : viz::makeTechnique(id)->params()) {
                if (p.name != name || p.components.empty()) continue;
                if (p.components.size() != parts.size())
                    throw InputError("--set " + name + ": '" + value + "' needs " + std::to_string(p.components.size()) +
                                     " numbers separated by x");
                for (std::size_t i = 0; i < parts.size(); ++i)
                    into[p.components[i]] = parseNumber(parts[i], "--set " + name);
                return;
            }
        }
        if (consulted.size() == 1)
            throw InputError("--set " + name + ": " + technique + " takes one number, not '" + value + "'");
        throw InputError("--set " + name + ": '" + value + "' is not a number (no technique takes " + name +
                         " per axis)");
    }
    // A word is one of the parameter's named values (ParamInfo::choices).
    if (!value.empty() && std::isalpha(static_cast<unsigned char>(value[0]))) {
        std::vector<std::string> known;
        for (const std::string& id : consulted) {
            const viz::ParamInfo* p = viz::findParam(*viz::makeTechnique(id), name);
            if (!p) continue;
            for (std::size_t i = 0; i < p->choices.size(); ++i) {
                if (p->choices[i] == value) {
                    into[name] = double(i);
                    return;
                }
                if (std::find(known.begin(), known.end(), p->choices[i]) == known.end()) known.push_back(p->choices[i]);
            }
        }
        if (!known.empty()) {
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            throw InputError("--set " + name + ": '" + value + "' is not one of " + list);
        }
    }
    into[name] = parseNumber(value, "--set " + name);
}

const std::string* firstRefusal(const std::map<std::string, Refusals>& errors, const std::string& technique) {
    const auto it = errors.find(technique);
    return it == errors.end() || it->second.empty() ? nullptr : &it->second.begin()->second;
}

SettingsByTechnique settingsByTechnique(const std::vector<std::string>& texts, const std::vector<std::string>& techniques,
                                        const std::string& noneHasIt) {
    SettingsByTechnique out;
    std::vector<bool> taken(texts.size(), false);
    for (const std::string& id : techniques) {
        const auto technique = viz::makeTechnique(id);
        viz::Settings& own = out.settings[id];
        for (std::size_t i = 0; i < texts.size(); ++i) {
            const std::string name = texts[i].substr(0, texts[i].find('='));
            if (!viz::findParam(*technique, name)) continue;
            taken[i] = true;
            viz::Settings one;
            try {
                parseSetting(texts[i], one, id);
            } catch (const InputError& e) {
                out.errors[id].try_emplace(name, id + ": " + e.what());
                continue;
            }
            own.insert(one.begin(), one.end());
        }
    }
    for (std::size_t i = 0; i < texts.size(); ++i) {
        if (taken[i]) continue;
        viz::Settings one;
        parseSetting(texts[i], one, "");  // a malformed text says so first
        throw InputError("--set " + texts[i].substr(0, texts[i].find('=')) + ": " + noneHasIt);
    }
    return out;
}

}  // namespace airlight
