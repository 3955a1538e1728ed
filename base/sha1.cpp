#include "base/sha1.h"

#include <openssl/evp.h>

#include <stdexcept>

namespace hsb {

struct Sha1::Context {
  EVP_MD_CTX* md = nullptr;
};

Sha1::Sha1() : context_(std::make_unique<Context>()) {
  context_->md = EVP_MD_CTX_new();
  if (!context_->md || EVP_DigestInit_ex(context_->md, EVP_sha1(), nullptr) != 1)
    throw std::runtime_error("OpenSSL cannot start a SHA-1 digest");
}

Sha1::~Sha1() { EVP_MD_CTX_free(context_->md); }

void Sha1::append(const void* data, std::size_t size) {
  if (size > 0 && EVP_DigestUpdate(context_->md, data, size) != 1) throw std::runtime_error("OpenSSL's SHA-1 failed");
}

std::string Sha1::hex() {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(context_->md, digest, &length) != 1) throw std::runtime_error("OpenSSL's SHA-1 failed");
  static const char digits[] = "0123456789ABCDEF";
  std::string text;
  for (unsigned int i = 0; i < length; ++i) {
    text += digits[digest[i] >> 4];
    text += digits[digest[i] & 15];
  }
  return text;
}

std::string sha1_hex(std::string_view text) {
  Sha1 hash;
  hash.append(text.data(), text.size());
  return hash.hex();
}

}  // namespace hsb
