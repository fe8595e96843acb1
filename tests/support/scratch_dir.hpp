#pragma once
// A folder of its own for a test that writes files. ctest runs tests in parallel, each in its own
// process, and a CI run may share the machine's temporary folder with another run of the suite: a
// fixed name (or gtest's random_seed(), 0 unless shuffling) let one test's clean-up delete the
// files another was still reading. The name holds the process id and the running test's full
// name, so no two live tests share it. The folder starts empty and is removed with the object.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace gizmo::test {

class ScratchDir {
 public:
  ScratchDir() {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = "gizmo-" + std::to_string(::getpid());
    if (test) name += std::string("-") + test->test_suite_name() + "." + test->name();
    for (char& c : name)
      if (c == '/') c = '_';  // parameterised tests' names hold a '/'
    path_ = std::filesystem::path(::testing::TempDir()) / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;  // a destructor must not throw; a left-over folder harms no later run
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& file) const { return path_ / file; }

 private:
  std::filesystem::path path_;
};

}  // namespace gizmo::test
