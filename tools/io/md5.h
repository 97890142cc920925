// MD5 message digest (RFC 1321), for the checksums an ISO 5436-2 X3P file carries
// (bindata/data.bin and main.xml). Not for security: X3P simply specifies MD5.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace scallop {

class Md5 {
 public:
  Md5();
  void update(const void* data, size_t bytes);
  // The digest as 32 lower-case hex digits; the object is spent afterwards.
  std::string hexDigest();

 private:
  void block(const unsigned char* p);
  uint32_t state_[4];
  uint64_t length_ = 0;  // bytes seen
  unsigned char buffer_[64];
};

std::string md5Hex(const std::string& bytes);

}  // namespace scallop
