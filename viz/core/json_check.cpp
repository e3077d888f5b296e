#include "core/json_check.h"

#include <nlohmann/json.hpp>

namespace viz {
namespace {

class DepthCheck {
public:
    explicit DepthCheck(int maxDepth) : mMax(maxDepth) {}
    bool tooDeep = false;
    std::string error;

    bool null() { return true; }
    bool boolean(bool) { return true; }
    bool number_integer(nlohmann::json::number_integer_t) { return true; }
    bool number_unsigned(nlohmann::json::number_unsigned_t) { return true; }
    bool number_float(nlohmann::json::number_float_t, const std::string&) { return true; }
    bool string(std::string&) { return true; }
    bool binary(nlohmann::json::binary_t&) { return true; }
    bool start_object(std::size_t) { return enter(); }
    bool key(std::string&) { return true; }
    bool end_object() { return leave(); }
    bool start_array(std::size_t) { return enter(); }
    bool end_array() { return leave(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
        // nlohmann's messages start with "[json.exception.parse_error.101] ": keep the readable part.
        error = e.what();
        const std::size_t bracket = error.find("] ");
        if (error.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) error = error.substr(bracket + 2);
        if (error.size() > 160) error = error.substr(0, 157) + "...";
        return false;
    }

private:
    bool enter() {
        if (++mDepth > mMax) {
            tooDeep = true;
            return false;
        }
        return true;
    }
    bool leave() {
        --mDepth;
        return true;
    }
    int mMax;
    int mDepth = 0;
};

}  // namespace

std::string jsonProblem(const std::string& text, int maxDepth) {
    DepthCheck check(maxDepth);
    const bool ok = nlohmann::json::sax_parse(text, &check, nlohmann::json::input_format_t::json, true);
    if (check.tooDeep) return "JSON nested deeper than " + std::to_string(maxDepth);
    if (!ok) return "malformed JSON (" + (check.error.empty() ? std::string("unexpected input") : check.error) + ")";
    return {};
}

}  // namespace viz
