// The campaign file's SHA-256 (results.json campaign_sha256) against the published vectors:
// the digest library may change (it did, for start-up cost), the digest may not.
#include "rig/campaign/file_digest.hpp"

#include <gtest/gtest.h>

#include <string>

namespace hilrig::campaign {
namespace {

// FIPS 180-2, Appendix B.1 ("abc", one block), B.2 (448 bits: the padding needs a second
// block) and B.3 (one million 'a'), and the empty message.
TEST(FileDigest, Sha256MatchesTheFips180Vectors) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

// Bytes, not text: an embedded NUL and a high byte are hashed like any other.
TEST(FileDigest, HashesEveryByteOfTheFile) {
  const std::string with_nul("a\0b", 3);
  EXPECT_NE(sha256_hex(with_nul), sha256_hex("a"));
  EXPECT_NE(sha256_hex(with_nul), sha256_hex("ab"));
  EXPECT_NE(sha256_hex("\xff"), sha256_hex("\x7f"));
  EXPECT_EQ(sha256_hex(with_nul).size(), 64U);
}

} // namespace
} // namespace hilrig::campaign
