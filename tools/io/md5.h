// MD5 message digest (RFC 1321), for the checksums an ISO 5436-2 X3P file carries
// (bindata/data.bin and main.xml) and the band files' checks. Not for security: X3P
// simply specifies MD5. Computed by Nettle (Debian's nettle-dev).
#pragma once

#include <nettle/md5.h>

#include <cstddef>
#include <string>

namespace scallop {

class Md5 {
 public:
  Md5();
  void update(const void* data, size_t bytes);
  // The digest as 32 lower-case hex digits; the object is spent afterwards.
  std::string hexDigest();

 private:
  md5_ctx context_;
};

std::string md5Hex(const std::string& bytes);

}  // namespace scallop
