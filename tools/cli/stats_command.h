// `scallop stats FILE.gsf|FILE.exr`: ISO 25178-2 height parameters of a height map
// (analysis/surface_metrology.h) over the whole map or a --region, with or without
// plane levelling, and optionally a --profile's roughness (analysis/profile_metrology.h).
// Its "surface_stats" block is the one every report.json of `simulate` carries
// (tools/run/report.h). Added to the command line by addStatsCommand (command.h).
#pragma once
