// airlight: command-line entry point. Every user error prints one line "airlight: error: ..." and exits
// with code 2; an internal failure exits with 1.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "animate_command.h"
#include "cli_args.h"
#include "commands.h"
#include "compare_command.h"
#include "lesson.h"
#include "bench_command.h"
#include "probe_command.h"
#include "report_command.h"
#include "core/error.h"
#include "gl/gl_error.h"

namespace {

constexpr const char* kUsage = R"(airlight - a visual debugger for volumetric shadows (single-scattering airlight)

usage: airlight [COMMAND] [OPTIONS]

commands:
  (none)          open the window on the default scene; without a display, render it
                  headlessly into out/ (final frame and every intermediate as PNG)
  gui             open the window (options as for render: --scene, --technique, --size, --set)
  --lesson NAME   open the window with the lesson player (lessons/NAME.md or a .md path; PageUp/
                  PageDown step, T try it, B back to the step, Space play/pause an animation)
  render          render one image:  airlight render --scene S --technique T --size WxH --out F.exr|F.png
  animate         frames along a motion path:  airlight animate --scene S --technique T --path P --frames N
                  --size WxH --out F.gif|F.mp4|DIR/
  list            list scenes | techniques | stages T | params T
  plan            show which stages and features a technique runs for a scene, and why
  export-scene    write a scene as glTF:  airlight export-scene NAME out.gltf|out.glb
  report          error against run time of every technique on each scene (CSV, JSON, plots, HTML)
  bench           how each technique's cost per stage grows with image size, shadow-map size, VPL
                  count and scene triangles (CSV, log-log plots with fitted exponents, HTML)
  probe           what this GL renderer does per second with each kind of work the techniques are
                  made of: arithmetic in compute and in fragment shaders, blending, triangles
  compare         error figures of one image against another:  airlight compare TEST.exr REFERENCE.exr
  lesson          a guided walkthrough: airlight lesson NAME opens it in the window (as --lesson NAME);
                  airlight lesson NAME --export DIR [--size WxH] renders every step and writes
                  DIR/index.html (lessons/NAME.md)

Run 'airlight COMMAND --help' for the options of a command.
)";

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> words(argv + 1, argv + argc);
    try {
        if (words.empty()) return airlight::runDefault();
        const std::string command = words.front();
        airlight::Args args({words.begin() + 1, words.end()});
        if (airlight::isHelpFlag(command)) {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (command == "render") return airlight::runRender(args);
        if (command == "animate") return airlight::runAnimate(args);
        if (command == "list") return airlight::runList(args);
        if (command == "plan") return airlight::runPlan(args);
        if (command == "export-scene") return airlight::runExportScene(args);
        if (command == "gui") return airlight::runGuiCommand(args);
        if (command == "compare") return airlight::runCompare(args);
        if (command == "probe") return airlight::runProbeCommand(args);
        if (command == "--lesson") {
            airlight::Args all(words);  // --lesson NAME and any window options
            return airlight::runGuiCommand(all);
        }
        if (command == "lesson") {
            if (args.empty() || airlight::isHelpFlag(args.peek())) {
                std::fputs("usage: airlight lesson NAME [--size WxH] [window options]\n"
                           "       airlight lesson NAME --export DIR [--size WxH]\n\n"
                           "Opens lessons/NAME.md (or a .md path) in the window's lesson player, or with --export renders\n"
                           "every step headlessly (each view it names as PNG) and writes DIR/index.html with the text and\n"
                           "images.\n",
                           stdout);
                return 0;
            }
            const std::string name = args.take();
            if (name.empty()) throw viz::InputError("lesson needs a NAME (run 'airlight lesson --help')");
            if (std::find(words.begin(), words.end(), "--export") == words.end()) {
                // No export: the lesson player in the window, with the window's options.
                std::vector<std::string> gui = {"--lesson", name};
                while (!args.empty()) gui.push_back(args.take());
                airlight::Args forward(gui);
                return airlight::runGuiCommand(forward);
            }
            std::string folder;
            glm::ivec2 size(0);
            while (!args.empty()) {
                const std::string flag = args.take();
                if (flag == "--export") folder = args.next(flag);
                else if (flag == "--size") size = airlight::parseSize(args.next(flag));
                else throw viz::InputError("unknown option '" + flag + "' for 'lesson'");
            }
            const airlight::Lesson lesson = airlight::parseLesson(airlight::findLesson(name));
            airlight::exportLesson(lesson, folder, size);
            std::printf("wrote %s/index.html (%zu steps)\n", folder.c_str(), lesson.steps.size());
            return 0;
        }
        if (command == "bench") {
            std::string line = "airlight";
            for (const std::string& w : words) line += " " + w;
            return airlight::runBenchCommand(args, line);
        }
        if (command == "report") {
            std::string line = "airlight";
            for (const std::string& w : words) line += " " + w;
            return airlight::runReportCommand(args, line);
        }
        throw viz::InputError("unknown command '" + command + "' (run 'airlight --help')");
    } catch (const viz::InputError& e) {
        std::fprintf(stderr, "airlight: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "airlight: internal error: %s\n", e.what());
        return 1;
    }
}
