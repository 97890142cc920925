#include "tools/run/job_loader.h"

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "sweep/input_error.h"
#include "tools/io/stl_io.h"
#include "tools/io/tool_path_file.h"
#include "tools/run/memory_limits.h"

namespace scallop {

namespace {

// The tool path of a job with "path": {"file": ...}, and the cutter from its CUTTER/
// when the job has no "tool".
void readPathFile(Job& job) {
  ToolPathFile read = readToolPathFile(job.pathFile);
  if (!job.hasTool && !read.cutter)
    throw InputError(
        "tool", "missing; expected an object (or a CUTTER/ statement in " + job.pathFile + ")");
  if (!job.hasTool) job.cutter = *read.cutter;
  if (job.hasTool && read.cutter &&
      (read.cutter->type != job.cutter.type || read.cutter->radius != job.cutter.radius ||
       read.cutter->cornerRadius != job.cutter.cornerRadius))
    read.warnings.add(job.pathFile,
                      "its CUTTER/ differs from the job's \"tool\"; the job's "
                      "tool is used");
  checkPathMagnitudes(read.path, read.moveLines, job.pathFile);
  warnRapidsIntoStock(read, job.cutter, job.stock, job.pathFile);
  job.path = std::move(read.path);
  job.moveLines = std::move(read.moveLines);
  job.pathWarnings = std::move(read.warnings);
  job.pathFormat = read.format;
}

}  // namespace

void loadJobInputs(Job& job, bool checkMemory) {
  try {
    if (checkMemory) checkGridFitsMemory(job.grid(), "grid.spacing");
    if (!job.designFile.empty())
      job.design = std::make_shared<const TriangleMesh>(readStl(job.designFile));
    if (job.isRaster) {
      checkRasterFitsMemory(job);
      job.path = makeRaster(job.cutter, job.stock, job.raster);
    } else {
      readPathFile(job);
    }
  } catch (const InputError& e) {
    throwFromJob(e, job.source);
  }
}

Job loadJob(const std::string& text, const std::string& source, bool checkMemory,
            const std::string& pathOverride) {
  Job job = parseJob(text, source, pathOverride);
  loadJobInputs(job, checkMemory);
  return job;
}

Job loadJobFile(const std::string& path, bool checkMemory, const std::string& pathOverride) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, "is a folder, expected a job file (JSON)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the job file");
  std::ostringstream text;
  text << in.rdbuf();
  return loadJob(text.str(), path, checkMemory, pathOverride);
}

}  // namespace scallop
