// tinygltf and stb_image compiled into the fuzz target, with coverage hooks and AddressSanitizer.
// The normal builds call Debian's libtinygltf.so, which carries neither: the fuzzer could not see
// branches inside the parser and ASan could not see its out-of-bounds reads. A definition in the
// executable takes precedence over the shared library's, so the loader's calls land here instead.
// The header is the one the shared library was built from (same package), so the types agree.
// UBSan stays off in this file: arithmetic quirks inside third-party decoders are not ours to report.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#include <tiny_gltf.h>
