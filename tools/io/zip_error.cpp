#include "tools/io/zip_error.h"

#include <zip.h>

namespace scallop {

std::string zipErrorText(int code) {
  zip_error_t e;
  zip_error_init_with_code(&e, code);
  const std::string text = zip_error_strerror(&e);
  zip_error_fini(&e);
  return text;
}

}  // namespace scallop
