#include "tools/cli/command.h"

#include <CLI/CLI.hpp>
#include <memory>
#include <sstream>
#include <string>

namespace scallop {

namespace {

// CLI11's formatter, but a command in the parent's list shows only its summary line.
class OneLineCommandFormatter : public CLI::Formatter {
 public:
  std::string make_subcommand(const CLI::App* sub) const override {
    const std::string& description = sub->get_description();
    std::ostringstream out;
    CLI::detail::format_help(out, sub->get_display_name(true),
                             description.substr(0, description.find('\n')), column_width_);
    return out.str();
  }
};

}  // namespace

void useOneLineCommandList(CLI::App& app) {
  app.formatter(std::make_shared<OneLineCommandFormatter>());
}

void addThreadsOption(CLI::App& command, CommonOptions& common) {
  command
      .add_option("--threads", common.threads,
                  "Worker threads (default: all cores); results do not depend on it")
      ->check(CLI::Range(0, 1 << 16));
}

}  // namespace scallop
