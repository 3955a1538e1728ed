#pragma once
// SHA-1 digests, as the pictures' metadata names scenes and data files by
// (hsb:scene_sha1, hsb:data_sha1): 40 upper-case hex digits. Computed by
// OpenSSL, whose SHA-1 uses the processor's SHA instructions where it has
// them (1.9 GB/s here, three times OpenImageIO's), and which hsb loads
// anyway; linking OpenImageIO's utility library for it cost every hsb
// process 25 MB at start-up (its string table).

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace hsb {

class Sha1 {
 public:
  Sha1();
  ~Sha1();
  Sha1(const Sha1&) = delete;
  Sha1& operator=(const Sha1&) = delete;
  void append(const void* data, std::size_t size);
  // The digest of all appended; the hash is spent after it.
  std::string hex();

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

std::string sha1_hex(std::string_view text);

}  // namespace hsb
