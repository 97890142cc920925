#include "tools/cli/cutter_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "tools/cli/command.h"

namespace scallop {

namespace {

struct CutterArgs {
  std::string tool, svg, title;
  bool json = false, list = false, pictures = false;
};

int runCutter(const CutterArgs& args) {
  if (args.list) {
    std::printf("%s", args.json ? (cutterShapesDocument().dump(2) + "\n").c_str()
                                : cutterShapesText().c_str());
    return 0;
  }
  if (args.pictures) {
    std::printf("%s", cutterPictureLines().c_str());
    return 0;
  }
  if (args.tool.empty()) {
    std::fprintf(stderr, "scallop cutter: error: give TOOL, --list or --pictures\n");
    return 2;
  }
  const Cutter cutter = cutterFromArgument(args.tool);
  if (!args.svg.empty())
    writeCutterSvg(cutter, args.title.empty() ? toString(cutter.type) : args.title, args.svg);
  if (args.json)
    std::printf("%s\n", cutterDocument(cutter).dump(2).c_str());
  else
    std::printf("%s", cutterTable(cutter).c_str());
  return 0;
}

}  // namespace

Command addCutterCommand(CLI::App& parent, CommonOptions& /*common*/) {
  auto args = std::make_shared<CutterArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "cutter",
      "Print a cutter's profile (lines and arcs) and draw it as SVG.\n"
      "The profile's lines and arcs run from the tip up (mm). TOOL is a cutter object as\n"
      "JSON text, e.g.\n"
      "'{\"type\": \"taper_ball\", \"tip_radius\": 1, \"taper_deg\": 5, \"flute_length\": 20}',\n"
      "or a file holding one or a job with \"tool\"; every type's keys: --list.");
  CLI::Option* tool =
      cmd->add_option("tool", args->tool, "Cutter object (JSON text) or cutter/job file");
  cmd->add_flag("--list", args->list,
                "Print every cutter type with its keys (unit, range) and an example (--json:\n"
                "as JSON)")
      ->excludes(tool);
  cmd->add_flag(
         "--pictures", args->pictures,
         "Print each example picture as 'file<TAB>title<TAB>tool' (scripts/cutter-images.sh)")
      ->excludes(tool);
  cmd->add_option("--svg", args->svg, "Write the profile picture (SVG) to this file");
  cmd->add_option("--title", args->title, "Title of the picture (default: the type)");
  cmd->add_flag("--json", args->json, "Print one JSON document (the profile) instead of a table");
  return {cmd, [args] { return runCutter(*args); }};
}

}  // namespace scallop
