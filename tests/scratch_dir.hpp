#pragma once
// A fresh, empty scratch directory per test, for tests that write files or run the
// executables: <tmp>/<prefix><test name>_<pid>. Removed when the test's fixture is destroyed,
// so a failed test leaves nothing behind either. ctest runs each test in its own process,
// hence the pid: two tests of one name in different suites or builds never share a directory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace dualhex::test {

/// `<tmp>/<prefix><current test's name>_<pid>`, emptied and created.
inline std::filesystem::path fresh_test_dir(const std::string& prefix) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = info ? info->name() : "outside_a_test";
    const auto dir = std::filesystem::temp_directory_path() / (prefix + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// Base of a fixture with a scratch directory `dir_` (gtest constructs the fixture after
/// setting the current test, so the name is known here).
class ScratchDirTest : public ::testing::Test {
protected:
    explicit ScratchDirTest(const std::string& prefix) : dir_(fresh_test_dir(prefix)) {}
    ~ScratchDirTest() override {
        std::error_code ignored;  // a destructor must not throw; a leftover dir is harmless
        std::filesystem::remove_all(dir_, ignored);
    }
    std::filesystem::path dir_;
};

}  // namespace dualhex::test
