#include "core/process_pipe.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "core/error.h"

extern char** environ;

namespace viz {

namespace {

// The last non-empty line of a file, at most 200 characters.
std::string lastLine(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::string line, last;
    while (std::getline(in, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    if (!last.empty() && last.back() == '\r') last.pop_back();
    return last.size() > 200 ? last.substr(0, 200) + "..." : last;
}

}  // namespace

std::string findOnPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    if (!path) return {};
    const std::string folders = path;
    for (std::size_t start = 0; start <= folders.size();) {
        std::size_t end = folders.find(':', start);
        if (end == std::string::npos) end = folders.size();
        const std::string folder = folders.substr(start, end - start);
        start = end + 1;
        if (folder.empty()) continue;  // an empty entry (the current folder) is not searched
        const std::string candidate = folder + "/" + name;
        struct stat st {};
        if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    return {};
}

ProcessPipe::ProcessPipe(const std::vector<std::string>& argv, const std::filesystem::path& logPath) : mLog(logPath) {
    VIZ_CHECK(!argv.empty(), "ProcessPipe: no program");
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw InputError("cannot start " + argv[0] + ": " + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, argv[0].c_str(), &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    if (rc != 0) {
        ::close(fds[1]);
        throw InputError("cannot start " + argv[0] + ": " + std::strerror(rc));
    }
    mPid = pid;
    mFd = fds[1];
    // A program that stops reading must not kill us with SIGPIPE: write() then fails with EPIPE.
    ::signal(SIGPIPE, SIG_IGN);
}

ProcessPipe::~ProcessPipe() {
    if (mPid > 0) (void)finish();
}

bool ProcessPipe::write(const void* data, std::size_t size) {
    const char* bytes = static_cast<const char*>(data);
    while (size > 0 && mFd >= 0) {
        const ssize_t n = ::write(mFd, bytes, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes += n;
        size -= std::size_t(n);
    }
    return mFd >= 0;
}

std::string ProcessPipe::finish() {
    if (mFd >= 0) ::close(mFd), mFd = -1;
    if (mPid <= 0) return "not running";
    int status = 0;
    while (::waitpid(mPid, &status, 0) < 0 && errno == EINTR) {
    }
    mPid = -1;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
    const std::string how = WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                              : "killed by signal " + std::to_string(WTERMSIG(status));
    const std::string line = lastLine(mLog);
    return line.empty() ? how : how + ": " + line;
}

}  // namespace viz
