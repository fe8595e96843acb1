// Key scripts: "TIME down|up KEYCODE" a line.
#include <gtest/gtest.h>

#include <string>

#include "gizmo/io/key_script.hpp"
#include "io_test_util.hpp"
#include "support/scratch_dir.hpp"

namespace gizmo::io {
namespace {

using namespace test;

std::vector<std::string> scriptErrors(const std::string& s) {
  return errorsOf([&] { readKeyScript(s, "k.keys"); });
}

TEST(KeyScript, ReadsInputsInOrder) {
  const auto in = readKeyScript("# flippers\n0 down 32\n\n1.25 up 32\r\n  1.25\tdown 81\n2 up 81", "k.keys");
  ASSERT_EQ(in.size(), 4u);
  EXPECT_EQ(in[0].time, 0.0);
  EXPECT_EQ(in[0].direction, KeyDirection::Down);
  EXPECT_EQ(in[0].key, 32);
  EXPECT_EQ(in[0].where.line, 2);
  EXPECT_EQ(in[0].where.column, 1);
  EXPECT_EQ(in[1].time, 1.25);
  EXPECT_EQ(in[1].direction, KeyDirection::Up);
  EXPECT_EQ(in[2].time, 1.25);  // equal times are allowed
  EXPECT_EQ(in[2].key, 81);
  EXPECT_EQ(in[2].where.line, 5);
  EXPECT_EQ(in[2].where.column, 3);
  EXPECT_EQ(in[3].time, 2.0);
  EXPECT_EQ(in[3].where.line, 6);
  EXPECT_TRUE(readKeyScript("", "k.keys").empty());
  EXPECT_TRUE(readKeyScript("\n# nothing\n", "k.keys").empty());
}

TEST(KeyScript, KeyCodeLimits) {
  const auto in = readKeyScript("0 down 0\n0 up 65535\n", "k.keys");
  EXPECT_EQ(in[1].key, 65535);
  EXPECT_EQ(scriptErrors("0 down 65536"),
            (std::vector<std::string>{"k.keys:1:8: error: key code 65536 is outside 0..65535"}));
  EXPECT_EQ(scriptErrors("0 down -1"),
            (std::vector<std::string>{"k.keys:1:8: error: key code -1 is outside 0..65535"}));
  EXPECT_EQ(
      scriptErrors("0 down 32.0"),
      (std::vector<std::string>{"k.keys:1:8: error: the key code must be written as a whole number, not '32.0'"}));
  EXPECT_EQ(scriptErrors("0 down space"),
            (std::vector<std::string>{"k.keys:1:8: error: the key code must be a number, not 'space'"}));
}

TEST(KeyScript, Times) {
  EXPECT_EQ(scriptErrors("-0.5 down 32"),
            (std::vector<std::string>{"k.keys:1:1: error: the time '-0.5' is negative; times start at 0"}));
  EXPECT_EQ(scriptErrors("1 down 32\n\n0.5 up 32"),
            (std::vector<std::string>{
                "k.keys:3:1: error: the time '0.5' is earlier than the time 1 on line 1; times must not decrease"}));
  EXPECT_EQ(scriptErrors("inf down 32"),
            (std::vector<std::string>{"k.keys:1:1: error: the time must be a finite number, not 'inf'"}));
  EXPECT_EQ(scriptErrors("1s down 32"),
            (std::vector<std::string>{"k.keys:1:1: error: the time must be a number, not '1s'"}));
  EXPECT_EQ(scriptErrors("1e400 down 32"),
            (std::vector<std::string>{"k.keys:1:1: error: the time '1e400' is out of range"}));
}

TEST(KeyScript, Shape) {
  EXPECT_EQ(scriptErrors("1 down"), (std::vector<std::string>{"k.keys:1:1: error: a key input is TIME down|up KEYCODE "
                                                              "(for example '1.25 down 32'); this line has 2 values"}));
  EXPECT_EQ(scriptErrors("  1"), (std::vector<std::string>{"k.keys:1:3: error: a key input is TIME down|up KEYCODE "
                                                           "(for example '1.25 down 32'); this line has 1 value"}));
  EXPECT_EQ(scriptErrors("1 down 32 33"),
            (std::vector<std::string>{"k.keys:1:11: error: unexpected '33': a key input is TIME down|up KEYCODE"}));
  EXPECT_EQ(scriptErrors("1 down 32 # space"),
            (std::vector<std::string>{"k.keys:1:11: error: unexpected '#': a key input is TIME down|up KEYCODE "
                                      "(comments must be on a line of their own)"}));
  EXPECT_EQ(scriptErrors("1 DOWN 32"),
            (std::vector<std::string>{"k.keys:1:3: error: the key direction must be down or up, not 'DOWN'"}));
  EXPECT_EQ(scriptErrors("1 down 32\x01"),
            (std::vector<std::string>{"k.keys:1:10: error: unexpected control character (byte 0x01)"}));
}

TEST(KeyScript, EveryErrorIsReported) {
  EXPECT_EQ(scriptErrors("1 press 32\n2 down 99999\n0 up 1\n"),
            (std::vector<std::string>{
                "k.keys:1:3: error: the key direction must be down or up, not 'press'",
                "k.keys:2:8: error: key code 99999 is outside 0..65535",
                "k.keys:3:1: error: the time '0' is earlier than the time 2 on line 2; times must not decrease"}));
}

TEST(KeyScript, Files) {
  const gizmo::test::ScratchDir dir;
  const std::string path = (dir / "run.keys").string();
  writeFile(path, "0.5 down 32\n0.75 up 32\n");
  const auto in = readKeyScriptFile(path);
  ASSERT_EQ(in.size(), 2u);
  EXPECT_EQ(in[1].time, 0.75);
  const std::string missing = (dir / "missing.keys").string();
  EXPECT_EQ(errorsOf([&] { readKeyScriptFile(missing); }),
            (std::vector<std::string>{missing + ": error: cannot read the file: it does not exist"}));
}

}  // namespace
}  // namespace gizmo::io
