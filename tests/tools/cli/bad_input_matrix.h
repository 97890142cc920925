// The bad-input matrix: one row per hostile input to one entry point, run
// through the real `scallop` binary. Every row must give its exit status (1 bad
// input, 2 usage error; CONVENTIONS.md), nothing on stdout, for status 1 exactly one
// line on stderr, "scallop: error: WHERE: WHAT", naming what the row lists, and no
// file left behind anywhere in the test's folder (temporaries included). Adding an
// entry point is adding rows: see bad_input_matrix_test.cpp and bad_input_files_test.cpp.
#pragma once

#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/cli_harness.h"

namespace scallop::test {

struct BadInputRow {
  std::string name;
  std::vector<std::pair<std::string, std::string>> files;  // written before the run
  std::string args;                                        // "@" stands for the test's folder
  int status;                                              // expected exit status
  std::vector<std::string> mentions;                       // each must appear in the message
};

// A row's input made from a template: `s` with its first `from` replaced by `to` (a
// template without `from` is a broken test, not a bad input).
inline std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  if (at == std::string::npos) throw std::logic_error("row template lacks " + from);
  return s.replace(at, from.size(), to);
}

class BadInputMatrix : public CliFixture {
 protected:
  static std::string expand(const std::string& args, const std::string& dir) {
    std::string s;
    for (char c : args) s += c == '@' ? dir : std::string(1, c);
    return s;
  }

  std::set<std::string> filesUnder() const {
    std::set<std::string> found;
    for (const auto& e : fs::recursive_directory_iterator(dir_))
      if (!e.is_directory()) found.insert(fs::relative(e.path(), dir_).string());
    return found;
  }

  void check(const BadInputRow& row) {
    SCOPED_TRACE(row.name);
    for (const auto& [name, bytes] : row.files) {
      fs::create_directories((dir_ / name).parent_path());
      std::ofstream(dir_ / name, std::ios::binary) << bytes;
    }
    const std::set<std::string> before = filesUnder();
    const CliRun r = run(expand(row.args, dir_.string()));
    EXPECT_EQ(r.status, row.status) << r.err;
    EXPECT_TRUE(r.out.empty()) << "stdout: " << r.out;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    if (row.status == 1) {
      EXPECT_EQ(r.err.rfind("scallop: error: ", 0), 0u) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line expected: " << r.err;
    }
    for (const std::string& m : row.mentions)
      EXPECT_NE(r.err.find(expand(m, dir_.string())), std::string::npos)
          << "the message does not name '" << m << "': " << r.err;
    const std::set<std::string> after = filesUnder();
    for (const std::string& f : after) EXPECT_TRUE(before.count(f)) << "left behind: " << f;
    // Clean up for the next row.
    for (const auto& e : fs::directory_iterator(dir_)) fs::remove_all(e.path());
  }
};

}  // namespace scallop::test
