// Feeding bytes to another program's standard input (ffmpeg, for video): POSIX spawn with a pipe, the
// program's own output kept in a file so that a failure can be named in one line.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace viz {

// The full path of an executable `name` in a folder of $PATH, or empty when there is none.
std::string findOnPath(const std::string& name);

class ProcessPipe {
public:
    // Starts argv[0] (a full path) with argv; its stdout and stderr go to `logPath`. Throws InputError
    // when it cannot start. The process then ignores SIGPIPE, so that a program that stops reading makes
    // write() return false instead of killing us.
    ProcessPipe(const std::vector<std::string>& argv, const std::filesystem::path& logPath);
    ~ProcessPipe();  // closes the pipe and waits for the program if finish() was not called
    ProcessPipe(const ProcessPipe&) = delete;
    ProcessPipe& operator=(const ProcessPipe&) = delete;

    // False when the program has stopped reading (it failed; finish() says how).
    bool write(const void* data, std::size_t size);
    // Closes its input and waits: empty when it exited with 0, else one line ("exit code 1: <its last
    // line of output>").
    std::string finish();

private:
    int mPid = -1;
    int mFd = -1;
    std::filesystem::path mLog;
};

}  // namespace viz
