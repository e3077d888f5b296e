// Errors. InputError is a problem with what the user gave us (a file, a flag, a value): the CLI prints
// its message as one line and exits with code 2. VIZ_CHECK is for programmer errors and is always on.
#pragma once

#include <stdexcept>
#include <string>

namespace viz {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

[[noreturn]] void checkFailed(const char* expr, const char* file, int line, const std::string& msg);

}  // namespace viz

#define VIZ_CHECK(cond, msg)                                                   \
    do {                                                                       \
        if (!(cond)) ::viz::checkFailed(#cond, __FILE__, __LINE__, (msg));     \
    } while (0)
