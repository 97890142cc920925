#!/bin/sh
# Quick start: install, build, and run the main job (the built-in default job:
# a bull cutter raster with lead) writing its height images into out/main/, then the
# validation run: the seeds' tables beside the simulated truth, into out/validation/.
set -eu
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh scallop  # the CLI alone: the tests are built by scripts/test.sh
./build/scallop simulate -o out/main "$@"
./build/scallop validate -o out/validation
echo "scallop: the height images are in $(pwd)/out/main/ (heights.exr, heights.gsf, preview.png, report.json)"
echo "scallop: the seed tables with their simulated columns are in $(pwd)/out/validation/ (*.csv, profiles/*.svg)"
