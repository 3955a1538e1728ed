// SHA-1 as the pictures' metadata stores it: FIPS 180's test vectors, in
// upper-case hex (as OpenImageIO wrote them before, so a picture's stored
// hash still matches its scene), whole or appended in pieces.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "base/sha1.h"

namespace hsb {
namespace {

TEST(Sha1, FipsVectorsInUpperCaseHex) {
  EXPECT_EQ(sha1_hex("abc"), "A9993E364706816ABA3E25717850C26C9CD0D89D");
  EXPECT_EQ(sha1_hex(""), "DA39A3EE5E6B4B0D3255BFEF95601890AFD80709");
  EXPECT_EQ(sha1_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "84983E441C3BD26EBAAE4AA1F95129E5E54670F1");
}

TEST(Sha1, PiecesHashAsTheWhole) {
  const std::string million(1000000, 'a');
  Sha1 pieces;
  for (std::size_t at = 0; at < million.size(); at += 65537)
    pieces.append(million.data() + at, std::min<std::size_t>(65537, million.size() - at));
  pieces.append(million.data(), 0);  // nothing, harmlessly
  EXPECT_EQ(pieces.hex(), "34AA973CD4C4DAA4F61EEB2BDBAD27316534016F");
  EXPECT_EQ(sha1_hex(million), "34AA973CD4C4DAA4F61EEB2BDBAD27316534016F");
}

}  // namespace
}  // namespace hsb
