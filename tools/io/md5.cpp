// Md5 (md5.h) on Nettle's MD5.
#include "tools/io/md5.h"

namespace scallop {

Md5::Md5() {
  md5_init(&context_);
}

void Md5::update(const void* data, size_t bytes) {
  md5_update(&context_, bytes, static_cast<const uint8_t*>(data));
}

std::string Md5::hexDigest() {
  uint8_t digest[MD5_DIGEST_SIZE];
  md5_digest(&context_, MD5_DIGEST_SIZE, digest);
  static const char* kHex = "0123456789abcdef";
  std::string out;
  for (const uint8_t byte : digest) {
    out += kHex[byte >> 4];
    out += kHex[byte & 15];
  }
  return out;
}

std::string md5Hex(const std::string& bytes) {
  Md5 md5;
  md5.update(bytes.data(), bytes.size());
  return md5.hexDigest();
}

}  // namespace scallop
