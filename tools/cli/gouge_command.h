// `scallop gouge`: seed 004's peripheral-milling strategy on an STL surface, and the
// exact check of every posture it accepts; the run itself is tools/run/gouge_run.h.
// Added to the command line by addGougeCommand (command.h).
#pragma once
