// splitSceneList: the scene lists of `report --scenes` and `bench --scenes`. A glTF path with a comma in
// its name stays one entry when the file exists (the pieces alone name nothing); names and other paths are
// split at every comma; an empty entry is a one-line error.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "run_info.h"
#include "temp_dir.h"

namespace airlight {
namespace {

TEST(SceneList, APathWithACommaStaysOneEntryWhenTheFileExists) {
    viz::testing::TempDir dir("scene_list");
    const std::string hall = (dir.path() / "my,hall.gltf").string();
    const std::string odd = (dir.path() / "a,b,c.glb").string();
    std::ofstream(hall) << "{}";
    std::ofstream(odd) << "";
    EXPECT_EQ(splitSceneList("grate," + hall + ",colonnade", "--scenes"),
              (std::vector<std::string>{"grate", hall, "colonnade"}));
    EXPECT_EQ(splitSceneList(odd + "," + hall, "--scenes"), (std::vector<std::string>{odd, hall}));
    EXPECT_EQ(splitSceneList("grate,terrain", "--scenes"), (std::vector<std::string>{"grate", "terrain"}));
    // Not a file: split as written (the loader then names the piece it cannot find).
    const std::string missing = (dir.path() / "no,such.gltf").string();
    EXPECT_EQ(splitSceneList(missing, "--scenes").size(), 2u);
    EXPECT_THROW(splitSceneList("grate,,terrain", "--scenes"), viz::InputError);
    EXPECT_THROW(splitSceneList("grate,", "--scenes"), viz::InputError);
}

}  // namespace
}  // namespace airlight
