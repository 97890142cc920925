// Command: how a `scallop` subcommand plugs into main.cpp. Each command file defines
// one `Command addXxxCommand(CLI::App& parent, CommonOptions& common)` that declares
// its options (binding them to its own state) and returns the function that runs it.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace scallop {

struct CommonOptions {
  int threads = 0;  // --threads N (0: all cores); main.cpp applies it before run()
};

struct Command {
  CLI::App* app = nullptr;
  // Returns the exit status; throws InputError for bad input (exit 1).
  std::function<int()> run;
};

// Adds `--threads` with the standard wording to a computing command.
void addThreadsOption(CLI::App& command, CommonOptions& common);

// Makes `scallop --help` list each command on one line: the first line of its
// description, which is therefore a whole sentence saying what the command does (the
// rest of the description is for `scallop COMMAND --help`). Call before adding commands.
void useOneLineCommandList(CLI::App& app);

Command addSimulateCommand(CLI::App& parent, CommonOptions& common);
Command addSurfaceCommand(CLI::App& parent, CommonOptions& common);
Command addGougeCommand(CLI::App& parent, CommonOptions& common);
Command addIntervalCommand(CLI::App& parent, CommonOptions& common);
Command addValidateCommand(CLI::App& parent, CommonOptions& common);
Command addBenchCommand(CLI::App& parent, CommonOptions& common);
Command addMergeCommand(CLI::App& parent, CommonOptions& common);
Command addStatsCommand(CLI::App& parent, CommonOptions& common);
Command addExportCommand(CLI::App& parent, CommonOptions& common);
Command addCollectCommand(CLI::App& parent, CommonOptions& common);
Command addCutterCommand(CLI::App& parent, CommonOptions& common);
Command addRenderCommand(CLI::App& parent, CommonOptions& common);

}  // namespace scallop
