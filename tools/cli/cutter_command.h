// `scallop cutter TOOL [--svg FILE] [--json]`: prints a cutter's profile (type, largest
// radius, flute length, each line and arc from the tip up) and draws it, so a user can
// check a description before simulating with it (tools/run/cutter_description.h).
// Added to the command line by addCutterCommand (command.h).
#pragma once

#include "tools/run/cutter_description.h"
