#include "command_options.h"

#include <cmath>

#include "core/error.h"
#include "scene/builtin_scenes.h"
#include "techniques/registry.h"

namespace airlight {

using viz::InputError;

CommonOptions parseOptions(Args& args, const std::string& command, const std::string& allowed, int maxFrames) {
    CommonOptions o;
    o.request.scene = viz::scene::defaultSceneName();
    o.request.technique = kDefaultTechnique;
    o.request.width = 320;
    o.request.height = 240;
    while (!args.empty()) {
        const std::string flag = args.take();
        if (allowed.find(" " + flag + " ") == std::string::npos)
            throw InputError("unknown option '" + flag + "' for '" + command + "' (run 'airlight " + command +
                             " --help')");
        if (flag == "--scene") o.request.scene = args.next(flag), o.sceneGiven = true;
        else if (flag == "--technique") o.request.technique = args.next(flag), o.techniqueGiven = true;
        else if (flag == "--state") o.state = args.next(flag);
        else if (flag == "--script") o.script = args.next(flag);
        else if (flag == "--export-dir") o.exportDir = args.next(flag);
        else if (flag == "--lesson") o.lesson = args.next(flag);
        else if (flag == "--ui-scale") {
            const double scale = parseNumber(args.next(flag), flag);
            if (!(scale >= 0.5 && scale <= 4.0)) throw InputError("--ui-scale must be a number from 0.5 to 4");
            o.uiScale = float(scale);
        }
        else if (flag == "--size") {
            const glm::ivec2 size = parseSize(args.next(flag));
            o.request.width = size.x, o.request.height = size.y;
            o.sizeGiven = true;
        } else if (flag == "--out") o.out = args.next(flag);
        else if (flag == "--layer") o.layer = args.next(flag);
        else if (flag == "--layer-index") o.layerIndex = parseWholeNumber(args.next(flag), flag, 0, 1 << 16);
        else if (flag == "--set") o.sets.push_back(args.next(flag));
        else if (flag == "--stop-after") o.request.stopAfter = args.next(flag);
        else if (flag == "--preset") {
            o.preset = args.next(flag);
            if (o.preset != "paper" && o.preset != "default")
                throw InputError("--preset '" + o.preset + "': expected 'paper' or 'default'");
        }
        else if (flag == "--exposure") {
            // A scale: 0 or less would write a black image, with no word of why.
            o.exposure = args.next(flag);
            if (o.exposure != "auto" && !(parseNumber(o.exposure, flag) > 0.0))
                throw InputError("--exposure must be auto or a scale above 0 (1 writes the values as they are), not '" +
                                 o.exposure + "'");
        }
        else if (flag == "--quiet") o.quiet = true;
        else if (flag == "--no-default-light") o.request.load.defaultLight = false;
        else if (flag == "--strict") o.strict = true;
        else if (flag == "--count-work") o.countWork = true;
        else if (flag == "--count-pixel") {
            const std::string text = args.next(flag);
            const std::size_t comma = text.find(',');
            if (comma == std::string::npos) throw InputError("--count-pixel expects X,Y (column, row from the top), got '" + text + "'");
            const double x = parseNumber(text.substr(0, comma), flag), y = parseNumber(text.substr(comma + 1), flag);
            if (x != std::floor(x) || y != std::floor(y) || x < 0 || y < 0)
                throw InputError("--count-pixel expects two whole numbers X,Y from 0, got '" + text + "'");
            o.countPixel = glm::ivec2(int(x), int(y));
            o.countWork = true;
        }
        else if (flag == "--screenshot") o.screenshot = args.next(flag);
        else if (flag == "--frames") {
            o.frames = parseWholeNumber(args.next(flag), flag, 1, maxFrames);
            o.framesGiven = true;
        } else if (flag == "--path") o.path = args.next(flag);
        else if (flag == "--path-frames") {
            o.pathFrames = parseWholeNumber(args.next(flag), flag, 2, 100000);
        }
        else if (flag == "--exr") o.exr = true;
        else if (flag == "--fps") o.fps = parseWholeNumber(args.next(flag), flag, 1, 100);
    }
    // Read once the technique is known: a named value's number is that technique's.
    for (const std::string& text : o.sets) parseSetting(text, o.request.settings, o.request.technique);
    // The paper's settings under the ones given with --set (those win).
    if (o.preset == "paper") {
        for (const auto& [name, value] : viz::makeTechnique(o.request.technique)->paperSettings())
            o.request.settings.emplace(name, value);
    }
    return o;
}

}  // namespace airlight
