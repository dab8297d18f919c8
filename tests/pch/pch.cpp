// Compiled only to make the precompiled header of its folder's tests (tests/CMakeLists.txt).
