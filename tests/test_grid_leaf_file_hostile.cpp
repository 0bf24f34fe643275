// Leaf files against hostile input (issue 15): non-regular files are refused without being
// read (a FIFO would block, /dev/zero never ends), a NUL or control byte cannot cut or
// garble the message, and integers are decimal ("+-0" is not).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dualhex/grid/input_error.hpp"
#include "dualhex/grid/leaf_file.hpp"

using namespace dualhex;
namespace fs = std::filesystem;

namespace {

struct Dir {
    fs::path path = fs::temp_directory_path() / ("dualhex_leaf_hostile_" + std::to_string(::getpid()));
    Dir() { fs::create_directories(path); }
    ~Dir() { fs::remove_all(path); }
};

std::string read_error(const fs::path& path) {
    try {
        (void)read_leaf_file(path);
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path.string());
        return e.what();
    }
    ADD_FAILURE() << path << " was accepted";
    return {};
}

std::string parse_error(const std::string& text) {
    try {
        (void)parse_leaves(text, "t.leaves");
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "accepted: " << text;
    return {};
}

TEST(LeafFileHostile, NonRegularFilesAreRefused) {
    Dir dir;
    EXPECT_NE(read_error("/dev/zero").find("/dev/zero: not a regular file"), std::string::npos);
    EXPECT_NE(read_error("/dev/null").find("not a regular file"), std::string::npos);
    const fs::path fifo = dir.path / "pipe.leaves";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(read_error(fifo).find("not a regular file"), std::string::npos);  // would block if opened
    EXPECT_NE(read_error(dir.path).find("not a regular file"), std::string::npos);
    EXPECT_NE(read_error(dir.path / "none.leaves").find("no such file"), std::string::npos);
    // A regular file is still read.
    std::ofstream(dir.path / "root.leaves") << "0 0 0 0\n";
    EXPECT_EQ(read_leaf_file(dir.path / "root.leaves").size(), 1u);
}

TEST(LeafFileHostile, ControlBytesAreEscapedNotCut) {
    const std::string text = std::string("0 0 0 \0x\n", 9);
    const std::string msg = parse_error(text);
    EXPECT_EQ(msg.find('\0'), std::string::npos);
    EXPECT_NE(msg.find("t.leaves:1: "), std::string::npos) << msg;
    EXPECT_NE(msg.find("\\x00x"), std::string::npos) << msg;
    EXPECT_NE(parse_error("0 0 0 \x1b[2J\n").find("\\x1b[2J"), std::string::npos);
    // The message continues after the NUL: the whole offending line is shown.
    EXPECT_NE(parse_error(std::string("1 0 \0 0 0 tail\n", 15)).find("tail"), std::string::npos);
}

TEST(LeafFileHostile, OnlyDecimalIntegers) {
    for (const char* bad : {"+-0", "+-1", "-+1", "++1", "0x1", "1e0", "1.0", "+", "-", "1,0"}) {
        SCOPED_TRACE(bad);
        const std::string msg = parse_error(std::string("0 ") + bad + " 0 0\n");
        EXPECT_NE(msg.find(std::string("'") + bad + "'"), std::string::npos) << msg;
    }
    // What the format allows: an optional sign before digits.
    EXPECT_EQ(parse_leaves("+0 0 +0 -0\n", "t.leaves").size(), 1u);
}

}  // namespace
