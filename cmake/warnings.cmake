# viz_warnings: one INTERFACE target that every first-party target links.
add_library(viz_warnings INTERFACE)
target_compile_options(viz_warnings INTERFACE
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
# A unity build (the ci and fuzz presets: CMAKE_UNITY_BUILD, 8 sources per compiler run) compiles each
# .cpp as if included by another, so GCC's warning about a class in an anonymous namespace used as the base
# of a class "in a header" fires on every test fixture; it does not apply to sources, so it is turned off.
if(CMAKE_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(viz_warnings INTERFACE -Wno-subobject-linkage)
endif()
if(VIZ_WERROR)
    target_compile_options(viz_warnings INTERFACE -Werror)
endif()
if(VIZ_SANITIZE)
    add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
    add_link_options(-fsanitize=address,undefined)
endif()
