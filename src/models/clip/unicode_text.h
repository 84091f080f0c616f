#pragma once
// UTF-8 <-> UTF-32 and the Unicode properties the CLIP tokenizer needs (through ICU, Debian
// libicu-dev): general categories (\p{L}, \p{N}), White_Space, NFC/NFKC and Python-style
// full lower-casing (str.lower(): unconditional SpecialCasing, final sigma, no locale).
#include <string>

namespace cls::clip {

// Invalid UTF-8 sequences become U+FFFD (Python would not have such a str at all).
std::u32string utf8_to_utf32(const std::string& s);
std::string utf32_to_utf8(const std::u32string& s);
void append_utf8(std::string& out, char32_t c);

bool is_letter(char32_t c);      // \p{L}: Lu Ll Lt Lm Lo
bool is_number(char32_t c);      // \p{N}: Nd Nl No
// \s of the regex module / Python str.isspace(): the White_Space property plus U+001C..U+001F.
bool is_space(char32_t c);

std::u32string nfc(const std::u32string& s);
std::u32string nfkc(const std::u32string& s);
std::u32string to_lower(const std::u32string& s);
std::u32string to_upper(const std::u32string& s);  // Python str.upper()

}  // namespace cls::clip
