// The precompiled header of the test executables (tests/CMakeLists.txt): QtTest, with the Qt
// modules a test links, and Eigen where the test links the core. Their headers are most of a
// test's compile time, and every test parses them; precompiled once for the tests of a folder
// that share their flags, a test compiles in a fraction of the time.
#pragma once

#if __has_include(<Eigen/Core>)
#include <Eigen/Core>
#endif
#include <QtTest>
