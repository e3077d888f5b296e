// Empty: the target viz_test_pch exists to precompile the test binaries' common headers (tests/CMakeLists.txt).
