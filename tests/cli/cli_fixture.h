// The fixture of the command-line tests: runs the airlight binary in a fresh folder per test and checks
// the one-line error contract.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "temp_dir.h"

namespace viz::testing {

namespace fs = std::filesystem;

struct RunResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

inline std::string readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

class CliTest : public ::testing::Test {
protected:
    RunResult run(const std::string& args) {
        const fs::path out = mDir / "stdout.txt", err = mDir / "stderr.txt";
        // AIRLIGHT_TEST_EXE runs another binary (a long fuzz campaign on a copy while the tree rebuilds).
        const char* exe = std::getenv("AIRLIGHT_TEST_EXE");
        const std::string cmd = std::string(exe && *exe ? exe : AIRLIGHT_EXE) + " " + args + " >" + out.string() + " 2>" + err.string();
        const int status = std::system(cmd.c_str());
        RunResult r;
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.out = readFile(out);
        r.err = readFile(err);
        return r;
    }

    fs::path path(const std::string& name) const { return mDir / name; }

    fs::path writeText(const std::string& name, const std::string& text) const {
        const fs::path p = mDir / name;
        std::ofstream(p) << text;
        return p;
    }

    // Asserts a user error: exit code 2, exactly one line on stderr naming the problem, nothing on stdout.
    void expectUserError(const RunResult& r, const std::string& mentions) {
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(r.err.rfind("airlight: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(mentions), std::string::npos) << "expected '" << mentions << "' in: " << r.err;
    }

    TempDir mTemp{"cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name())};
    fs::path mDir = mTemp.path();
};

// Sets (or, given null, unsets) an environment variable while it lives, for the commands a test runs;
// the variable is put back as it was.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : mName(name) {
        if (const char* old = std::getenv(name)) mOld = old, mHad = true;
        if (value) ::setenv(name, value, 1);
        else ::unsetenv(name);
    }
    ~ScopedEnv() {
        if (mHad) ::setenv(mName.c_str(), mOld.c_str(), 1);
        else ::unsetenv(mName.c_str());
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    std::string mName, mOld;
    bool mHad = false;
};

// Points the reference's disk cache (AIRLIGHT_CACHE_DIR) at `dir` while it lives, so a test neither
// reads frames another run left nor leaves its own behind.
class ScopedCacheDir {
public:
    explicit ScopedCacheDir(const fs::path& dir) : mEnv("AIRLIGHT_CACHE_DIR", dir.c_str()) {}

private:
    ScopedEnv mEnv;
};

// A CliTest that opens the window: skipped without a display (X11 or Wayland), a failure instead when
// VIZ_REQUIRE_DISPLAY=1 (CI runs these under xvfb-run).
class WindowCliTest : public CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        const char* x = std::getenv("DISPLAY");
        const char* w = std::getenv("WAYLAND_DISPLAY");
        if (!((x && *x) || (w && *w))) {
            const char* require = std::getenv("VIZ_REQUIRE_DISPLAY");
            if (require && std::string(require) == "1") FAIL() << "VIZ_REQUIRE_DISPLAY=1 but no display";
            GTEST_SKIP() << "no DISPLAY (run under xvfb-run -a)";
        }
    }
};

// `page` as headless Chromium loads it, through a copy that counts the images that failed to load:
// images "images=N missing=M" (empty when no browser is installed), and with a `png` path a screenshot
// of width x height CSS pixels taken in the same run (one browser start for both).
struct BrowserView {
    std::string images;
    bool screenshot = false;
};

inline BrowserView viewInBrowser(const fs::path& page, const fs::path& scratch, const fs::path& png = {}, int width = 0,
                                 int height = 0) {
    const char* browser = "/usr/bin/chromium";
    if (!fs::exists(browser)) return {};
    std::string html = readFile(page);
    const std::string probe =
        "<script>window.addEventListener('load',()=>{const i=[...document.images];"
        "document.body.setAttribute('data-probe','images='+i.length+' missing='+"
        "i.filter(x=>!x.complete||x.naturalWidth===0).length);});</script>";
    html.insert(html.rfind("</body>"), probe);
    const fs::path copy = page.parent_path() / "probe.html";
    std::ofstream(copy) << html;
    const fs::path dom = scratch / "dom.txt";
    std::string cmd = std::string(browser) +
                      " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                      "--disable-background-networking --disable-component-update --disable-sync "
                      "--hide-scrollbars --user-data-dir=" + (scratch / "profile").string() + " --virtual-time-budget=5000";
    if (!png.empty())
        cmd += " --window-size=" + std::to_string(width) + "," + std::to_string(height) + " --screenshot=" + png.string();
    cmd += " --dump-dom file://" + copy.string() + " >" + dom.string() + " 2>/dev/null";
    BrowserView view;
    if (std::system(cmd.c_str()) != 0) return {"browser failed", false};
    view.screenshot = !png.empty() && fs::exists(png);
    const std::string text = readFile(dom);
    const std::size_t at = text.find("data-probe=\"");
    if (at == std::string::npos) return {"no probe result", view.screenshot};
    const std::size_t first = at + 12;
    view.images = text.substr(first, text.find('"', first) - first);
    return view;
}

inline std::string imagesLoadedInBrowser(const fs::path& page, const fs::path& scratch) {
    return viewInBrowser(page, scratch).images;
}

// What an HTML validator (Debian's `tidy`, errors and warnings) says about `page`: empty when the page is
// valid, "no tidy" when tidy is not installed (a failure where VIZ_REQUIRE_BROWSER is set, as in CI).
inline std::string htmlValidatorComplaints(const fs::path& page, const fs::path& scratch) {
    if (!fs::exists("/usr/bin/tidy")) {
        if (std::getenv("VIZ_REQUIRE_BROWSER")) return "VIZ_REQUIRE_BROWSER is set but /usr/bin/tidy is missing";
        return {};
    }
    const fs::path report = scratch / "tidy.txt";
    const std::string cmd = "/usr/bin/tidy -q -e --gnu-emacs yes " + page.string() + " >/dev/null 2>" + report.string();
    const int status = std::system(cmd.c_str());
    const std::string text = readFile(report);
    return status == 0 && text.empty() ? std::string() : (text.empty() ? "tidy failed" : text);
}

}  // namespace viz::testing
