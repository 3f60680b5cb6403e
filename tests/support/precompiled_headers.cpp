// The one source of the precompiled-header targets oasis_test_pch17 and oasis_test_pch20
// (cmake/OasisTests.cmake): CMake builds a target's precompiled header with its first source, and
// the test executables reuse it. Nothing here is linked into a test.
