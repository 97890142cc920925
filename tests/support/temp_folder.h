// A GoogleTest fixture with a folder of its own for each test:
// <temp>/scallop-<prefix>-<pid>-<test name>, removed before and after the test (not
// created: a test of a run that must make its output folder starts without one).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace scallop::test {

class TempFolderTest : public ::testing::Test {
 protected:
  explicit TempFolderTest(const std::string& prefix) : prefix_(prefix) {}
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("scallop-" + prefix_ + "-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace scallop::test
