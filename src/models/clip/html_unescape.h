#pragma once
// HTML character references, decoded the way the CLIP tokenizer's pipeline does it.
#include <string>

namespace cls::clip {

// Python's html.unescape (3.11): named references of the HTML5 list (longest-prefix match for
// the legacy names without ';'), decimal/hex references with the HTML5 replacement rules
// (0x80-0x9F as windows-1252, surrogates and > U+10FFFF -> U+FFFD, control/noncharacters dropped).
std::u32string html_unescape(const std::u32string& text);

// ftfy.fixes.unescape_html (6.3): only complete references `&#?[0-9A-Za-z]{1,24};`; named ones
// from the HTML5 list (plus all-uppercase spellings of lower-case names, e.g. &EACUTE;), numeric
// ones through html.unescape.
std::u32string ftfy_unescape_html(const std::u32string& text);

// windows-1252 as ftfy's "sloppy" codec sees it: byte 0x80..0x9F -> its character, undefined
// bytes (0x81, 0x8D, 0x8F, 0x90, 0x9D) map to the C1 control of the same value.
char32_t cp1252_char(unsigned char byte);

}  // namespace cls::clip
