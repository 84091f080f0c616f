#include "models/clip/ftfy_fixes.h"

#include "models/clip/html_unescape.h"
#include "models/clip/unicode_text.h"

namespace cls::clip {
namespace {

// ESC '[' (digits | ';')* letter — ANSI terminal escapes.
std::u32string remove_terminal_escapes(const std::u32string& s) {
  if (s.find(U'\x1b') == std::u32string::npos) return s;
  std::u32string out;
  for (size_t i = 0; i < s.size();) {
    if (s[i] == 0x1B && i + 1 < s.size() && s[i + 1] == U'[') {
      size_t k = i + 2;
      while (k < s.size() && ((s[k] >= '0' && s[k] <= '9') || s[k] == ';')) ++k;
      if (k < s.size() && ((s[k] >= 'a' && s[k] <= 'z') || (s[k] >= 'A' && s[k] <= 'Z'))) {
        i = k + 1;
        continue;
      }
    }
    out.push_back(s[i++]);
  }
  return out;
}

// The byte a character stands for when UTF-8 was decoded as windows-1252 (or latin-1), or -1.
int mojibake_byte(char32_t c) {
  if (c <= 0xFF) return int(c);  // latin-1 (and the C1 controls the sloppy codec keeps)
  for (int b = 0x80; b <= 0x9F; ++b)
    if (cp1252_char(static_cast<unsigned char>(b)) == c) return b;
  return -1;
}

// Re-decodes every run "lead byte + continuation bytes" spelled in windows-1252/latin-1
// characters that forms one well-formed UTF-8 character.
std::u32string fix_utf8_mojibake(const std::u32string& s) {
  std::u32string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    const char32_t c0 = s[i];
    int len = 0;
    if (c0 >= 0xC2 && c0 <= 0xDF) len = 2;
    else if (c0 >= 0xE0 && c0 <= 0xEF) len = 3;
    else if (c0 >= 0xF0 && c0 <= 0xF4) len = 4;
    if (len > 0 && i + len <= s.size()) {
      std::string bytes(1, static_cast<char>(c0));
      bool ok = true;
      for (int k = 1; k < len && ok; ++k) {
        const int b = mojibake_byte(s[i + k]);
        ok = b >= 0x80 && b <= 0xBF;
        bytes.push_back(static_cast<char>(b));
      }
      if (ok) {
        const std::u32string dec = utf8_to_utf32(bytes);
        if (dec.size() == 1 && dec[0] != 0xFFFD) {
          out.push_back(dec[0]);
          i += len;
          continue;
        }
      }
    }
    out.push_back(c0);
    ++i;
  }
  return out;
}

std::u32string fix_c1_controls(std::u32string s) {
  for (char32_t& c : s)
    if (c >= 0x80 && c <= 0x9F) c = cp1252_char(static_cast<unsigned char>(c));
  return s;
}

// ftfy's LIGATURES: NFKC of "ĲĳĿŀŉǄǅǆǇǈǉǊǋǌǱǲǳﬀﬁﬂﬃﬄﬅﬆ".
bool is_latin_ligature(char32_t c) {
  return c == 0x132 || c == 0x133 || c == 0x13F || c == 0x140 || c == 0x149 ||
         (c >= 0x1C4 && c <= 0x1CC) || (c >= 0x1F1 && c <= 0x1F3) || (c >= 0xFB00 && c <= 0xFB06);
}

std::u32string fix_ligatures_and_width(const std::u32string& s) {
  std::u32string out;
  out.reserve(s.size());
  for (char32_t c : s) {
    if (c == 0x3000) {
      out.push_back(U' ');
    } else if (is_latin_ligature(c) || (c >= 0xFF01 && c <= 0xFFEF)) {
      out += nfkc(std::u32string(1, c));
    } else {
      out.push_back(c);
    }
  }
  return out;
}

std::u32string uncurl_quotes(std::u32string s) {
  for (char32_t& c : s) {
    if (c == 0x2BC || (c >= 0x2018 && c <= 0x201B)) c = U'\'';
    else if (c >= 0x201C && c <= 0x201F) c = U'"';
  }
  return s;
}

std::u32string fix_line_breaks(const std::u32string& s) {
  std::u32string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    const char32_t c = s[i];
    if (c == U'\r' && i + 1 < s.size() && s[i + 1] == U'\n') continue;  // "\r\n" -> "\n"
    out.push_back((c == U'\r' || c == 0x2028 || c == 0x2029 || c == 0x85) ? U'\n' : c);
  }
  return out;
}

bool is_removed_control(char32_t c) {
  return c <= 0x08 || c == 0x0B || (c >= 0x0E && c <= 0x1F) || c == 0x7F ||
         (c >= 0x206A && c <= 0x206F) || c == 0xFEFF || (c >= 0xFFF9 && c <= 0xFFFC);
}

std::u32string remove_control_chars(const std::u32string& s) {
  std::u32string out;
  out.reserve(s.size());
  for (char32_t c : s)
    if (!is_removed_control(c)) out.push_back(c);
  return out;
}

std::u32string fix_segment(std::u32string text, bool unescape_html) {
  for (;;) {
    const std::u32string before = text;
    if (unescape_html) text = ftfy_unescape_html(text);
    text = remove_terminal_escapes(text);
    text = fix_c1_controls(fix_utf8_mojibake(text));
    text = fix_ligatures_and_width(text);
    text = uncurl_quotes(std::move(text));
    text = fix_line_breaks(text);
    text = remove_control_chars(text);
    text = nfc(text);
    if (text == before) return text;
  }
}

}  // namespace

std::u32string ftfy_fix_text(const std::u32string& text) {
  std::u32string out;
  bool unescape_html = true;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find(U'\n', pos);
    end = end == std::u32string::npos ? text.size() : end + 1;
    const std::u32string segment = text.substr(pos, end - pos);
    if (segment.find(U'<') != std::u32string::npos) unescape_html = false;  // stays off
    out += fix_segment(segment, unescape_html);
    pos = end;
  }
  return out;
}

}  // namespace cls::clip
