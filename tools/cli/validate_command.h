// `scallop validate`: the validation run's tables printed (or one JSON document); the
// run itself, which writes the CSV tables and SVG pictures, is
// tools/run/validation_run.h. Added to the command line by addValidateCommand (command.h).
#pragma once
