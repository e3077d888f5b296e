# viz_warnings: one INTERFACE target that every first-party target links.
add_library(viz_warnings INTERFACE)
target_compile_options(viz_warnings INTERFACE
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
if(VIZ_WERROR)
    target_compile_options(viz_warnings INTERFACE -Werror)
endif()
if(VIZ_SANITIZE)
    add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
    add_link_options(-fsanitize=address,undefined)
endif()
