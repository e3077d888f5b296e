// Naming a lesson (app/lesson.h matchLesson): the full name in any case, its number, or as little of
// its name as stays one lesson's; ambiguous and unknown names pick none and say which could be meant.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lesson.h"

namespace airlight {
namespace {

const std::vector<std::string> kLessons = {"01-airlight-integral", "02-ray-marching", "03-slices",
                                           "04-polygonal-light-volumes", "05-epipolar-min-max",
                                           "06-voxelized-shadow-volumes", "07-choosing-a-technique", "12-extra"};

std::string pick(const std::string& name) {
    std::vector<std::string> matches;
    return matchLesson(name, kLessons, matches);
}

TEST(LessonName, AFullNameANumberOrAnUnambiguousPartPicksOneLesson) {
    for (const std::string& l : kLessons) EXPECT_EQ(pick(l), l);
    EXPECT_EQ(pick("03-SLICES"), "03-slices");
    EXPECT_EQ(pick("3"), "03-slices");
    EXPECT_EQ(pick("03"), "03-slices");
    EXPECT_EQ(pick("003"), "03-slices");
    EXPECT_EQ(pick("12"), "12-extra");
    EXPECT_EQ(pick("slices"), "03-slices");
    EXPECT_EQ(pick("min-max"), "05-epipolar-min-max");
    EXPECT_EQ(pick("05-epi"), "05-epipolar-min-max");
    EXPECT_EQ(pick("Ray"), "02-ray-marching");
    // A number is a lesson's number, never a part of a name: "1" is lesson 1, not 12.
    EXPECT_EQ(pick("1"), "01-airlight-integral");
}

TEST(LessonName, UnknownAndAmbiguousNamesPickNoneAndListTheCandidates) {
    std::vector<std::string> matches;
    EXPECT_EQ(matchLesson("", kLessons, matches), "");
    EXPECT_EQ(matchLesson("README", kLessons, matches), "");
    EXPECT_TRUE(matches.empty());
    EXPECT_EQ(matchLesson("8", kLessons, matches), "");
    EXPECT_EQ(matchLesson("0", kLessons, matches), "");
    EXPECT_EQ(matchLesson("99999999999999999999", kLessons, matches), "") << "too long for a number: no lesson";
    EXPECT_EQ(matchLesson("volumes", kLessons, matches), "");
    EXPECT_EQ(matches, (std::vector<std::string>{"04-polygonal-light-volumes", "06-voxelized-shadow-volumes"}));
    // A name's start wins over a part elsewhere: "0" alone is a number, "0-" no lesson's start or part.
    EXPECT_EQ(matchLesson("0-", kLessons, matches), "");
    EXPECT_TRUE(matches.empty());
}

}  // namespace
}  // namespace airlight
