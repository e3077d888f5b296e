# Every dependency comes from a Debian package; nothing is fetched at configure or build time.
# scripts/setup.sh installs them; the package names are listed there.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(glfw3 3.3 REQUIRED)
find_package(glm REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(embree 3 REQUIRED)
# oneTBB (Embree's own dependency): the reference's row-parallel loop.
find_package(TBB REQUIRED)
find_package(Eigen3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3 REQUIRED)
pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
# OpenImageIO through pkg-config: Debian's CMake package config names /usr/include/opencv4 as an include
# directory, which exists only when libopencv-dev happens to be installed.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)
# OpenEXR alone: the portable image codec of the bundle (viz/core/image_codec.h).
find_package(OpenEXR 3 REQUIRED)
find_package(Boost 1.74 REQUIRED)
# md4c: the lessons' Markdown (app/lesson_markdown.h). Through pkg-config: Debian's CMake package
# config also names libmd4c-html, a package of its own that we do not need.
pkg_check_modules(MD4C REQUIRED IMPORTED_TARGET md4c)
if(VIZ_BUILD_TESTS)
    find_package(GTest REQUIRED)
endif()

# glm: silence its own warnings by treating it as a system include.
if(TARGET glm::glm)
    get_target_property(_glm_inc glm::glm INTERFACE_INCLUDE_DIRECTORIES)
    set_target_properties(glm::glm PROPERTIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${_glm_inc}")
endif()
# Debian's tiny_gltf.h includes <stb_image.h>, which libstb-dev installs under /usr/include/stb.
add_library(viz_tinygltf INTERFACE)
target_link_libraries(viz_tinygltf INTERFACE TinyGLTF::TinyGLTF)
target_include_directories(viz_tinygltf SYSTEM INTERFACE /usr/include/stb)
