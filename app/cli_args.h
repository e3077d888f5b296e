// Small command-line parsing helpers: every malformed value is an InputError naming the flag.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "debug/technique.h"

namespace airlight {

class Args {
public:
    Args(std::vector<std::string> words) : mWords(std::move(words)) {}
    bool empty() const { return mPos >= mWords.size(); }
    const std::string& peek() const { return mWords[mPos]; }
    std::string next(const std::string& forFlag);  // InputError when missing
    std::string take() { return mWords[mPos++]; }

private:
    std::vector<std::string> mWords;
    std::size_t mPos = 0;
};

// The largest image side a render, a session or a lesson may ask for: 16384^2 float images (4 GiB each)
// do not fit the GL framebuffers and the reference's buffers on a 24 GiB machine; 8192^2 renders.
constexpr int kMaxImageSide = 8192;
glm::ivec2 parseSize(const std::string& text);                 // "WxH", 1..kMaxImageSide each
// "name=value" into `into`. A word is one of the named values of the parameter `name` (ParamInfo::choices)
// and AxBxC one number per component, both as `technique` declares them: the same word can stand for
// different numbers in different techniques (epipole=paper is 2 in vsv, 1 in ivsv). Where `technique` has
// no such parameter, the first technique that has one gives the meaning.
void parseSetting(const std::string& text, viz::Settings& into, const std::string& technique);
// Several --set texts for each of `techniques`: the ones naming a parameter it has, read as it declares
// them (`settings`); a text that technique refuses (a word not among its choices) is left out of its
// settings and its refusal kept in `errors` under the technique and the parameter's name, "ID: --set ...".
// A name none of `techniques` has is an InputError "--set NAME: " + noneHasIt.
using Refusals = std::map<std::string, std::string>;  // parameter name -> the one-line refusal
struct SettingsByTechnique {
    std::map<std::string, viz::Settings> settings;
    std::map<std::string, Refusals> errors;  // only techniques that refused something
};
// The first refusal kept for `technique` (by parameter name), or null when it refused nothing.
const std::string* firstRefusal(const std::map<std::string, Refusals>& errors, const std::string& technique);
SettingsByTechnique settingsByTechnique(const std::vector<std::string>& texts, const std::vector<std::string>& techniques,
                                        const std::string& noneHasIt);
double parseNumber(const std::string& text, const std::string& what);
// A whole number from lo to hi, else an InputError: "FLAG must be a whole number from LO to HI, not 'TEXT'".
int parseWholeNumber(const std::string& text, const std::string& flag, int lo, int hi);
bool isHelpFlag(const std::string& word);

}  // namespace airlight
