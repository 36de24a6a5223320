// UTF-8 for JSON (io/utf8_text.hpp), against an independent decoder written
// from RFC 3629 section 3 (the lead byte's bit pattern gives the length, the
// code point must need that many bytes, no surrogates D800-DFFF, nothing
// above U+10FFFF): valid_utf8 agrees with it on every string of one and two
// bytes and on random strings of three to six bytes; every code point's
// encoding is one sequence of its length; escape_invalid_utf8 writes each bad
// byte as \xNN and keeps everything else; utf8_for_json adds its note only
// when it changed something.
#include "io/utf8_text.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <string>

namespace ECCD_UNITY_ID {
using namespace eccd;

namespace {

std::string encode(unsigned cp) {  // RFC 3629's table, for any cp < 2^21
  std::string s;
  if (cp < 0x80) {
    s += char(cp);
  } else if (cp < 0x800) {
    s += char(0xC0 | (cp >> 6));
    s += char(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    s += char(0xE0 | (cp >> 12));
    s += char(0x80 | ((cp >> 6) & 0x3F));
    s += char(0x80 | (cp & 0x3F));
  } else {
    s += char(0xF0 | (cp >> 18));
    s += char(0x80 | ((cp >> 12) & 0x3F));
    s += char(0x80 | ((cp >> 6) & 0x3F));
    s += char(0x80 | (cp & 0x3F));
  }
  return s;
}

// The reference: decode sequence by sequence, from the bit patterns.
bool reference_valid(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const unsigned c = static_cast<unsigned char>(s[i]);
    std::size_t n;
    unsigned cp;
    if (c < 0x80) {
      n = 1;
      cp = c;
    } else if ((c & 0xE0) == 0xC0) {
      n = 2;
      cp = c & 0x1F;
    } else if ((c & 0xF0) == 0xE0) {
      n = 3;
      cp = c & 0x0F;
    } else if ((c & 0xF8) == 0xF0) {
      n = 4;
      cp = c & 0x07;
    } else {
      return false;
    }
    if (i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k) {
      const unsigned d = static_cast<unsigned char>(s[i + k]);
      if ((d & 0xC0) != 0x80) return false;
      cp = cp << 6 | (d & 0x3F);
    }
    const unsigned least[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < least[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
    i += n;
  }
  return true;
}

}  // namespace

TEST_CASE("valid_utf8 agrees with a decoder written from RFC 3629", "[io][utf8]") {
  for (int a = 0; a < 256; ++a) {
    const std::string one(1, char(a));
    CHECK(valid_utf8(one) == reference_valid(one));
    for (int b = 0; b < 256; ++b) {
      const std::string two{char(a), char(b)};
      if (valid_utf8(two) != reference_valid(two)) FAIL_CHECK("bytes " << a << " " << b);
    }
  }
  std::mt19937_64 rng(379);
  // bytes biased towards the interesting ones: lead bytes and continuations
  const unsigned char pool[] = {0x00, 0x2F, 0x41, 0x5C, 0x7F, 0x80, 0x8F, 0x90, 0x9F, 0xA0, 0xBF, 0xC0, 0xC1, 0xC2,
                                0xDF, 0xE0, 0xE1, 0xEC, 0xED, 0xEE, 0xEF, 0xF0, 0xF1, 0xF3, 0xF4, 0xF5, 0xFF};
  std::uniform_int_distribution<std::size_t> pick(0, sizeof pool - 1), len(3, 6);
  for (int trial = 0; trial < 200000; ++trial) {
    std::string s;
    for (std::size_t k = len(rng); k > 0; --k) s += char(pool[pick(rng)]);
    if (valid_utf8(s) != reference_valid(s)) FAIL_CHECK("trial " << trial << ": " << escape_invalid_utf8(s));
  }
}

TEST_CASE("each code point encodes to one sequence, but not surrogates, overlong forms or code points beyond U+10FFFF",
          "[io][utf8]") {
  for (unsigned cp = 0; cp <= 0x10FFFF; ++cp) {
    const std::string s = encode(cp);
    const bool surrogate = cp >= 0xD800 && cp <= 0xDFFF;
    const std::size_t n = utf8_sequence_length(s, 0);
    if (n != (surrogate ? 0 : s.size())) FAIL_CHECK("U+" << std::hex << cp);
  }
  CHECK_FALSE(valid_utf8(encode(0x110000)));
  CHECK_FALSE(valid_utf8("\xC0\xAF"));          // '/' in two bytes
  CHECK_FALSE(valid_utf8("\xE0\x80\xAF"));      // ... in three
  CHECK_FALSE(valid_utf8("\xF0\x80\x80\xAF"));  // ... in four
  CHECK_FALSE(valid_utf8("\xE2\x82"));          // '€' cut short
  CHECK(valid_utf8("\xE2\x82\xAC"));            // '€'
  CHECK(valid_utf8(""));
}

TEST_CASE("escape_invalid_utf8 and utf8_for_json: each bad byte shown by its hex code, the rest kept", "[io][utf8]") {
  CHECK(escape_invalid_utf8("a\xFF"
                            "b") == "a\\xFFb");
  CHECK(escape_invalid_utf8("\xE2\x82") == "\\xE2\\x82");                  // a cut sequence: both bytes shown
  CHECK(escape_invalid_utf8("x\\y \xE2\x82\xAC") == "x\\y \xE2\x82\xAC");  // a backslash and '€' kept
  CHECK(escape_invalid_utf8("\xED\xA0\x80") == "\\xED\\xA0\\x80");         // a surrogate
  CHECK(utf8_for_json("plain \xE2\x82\xAC") == "plain \xE2\x82\xAC");      // unchanged: no note
  CHECK(utf8_for_json("bad \x80") == std::string("bad \\x80") + kInvalidUtf8Note);
  // the escaped text is always valid UTF-8
  std::mt19937_64 rng(380);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string s;
    for (int k = 0; k < 12; ++k) s += char(rng() & 0xFF);
    CHECK(valid_utf8(escape_invalid_utf8(s)));
  }
}

}  // namespace ECCD_UNITY_ID
