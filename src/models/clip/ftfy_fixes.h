#pragma once
// The subset of ftfy.fix_text (ftfy 6.3, default TextFixerConfig) that the CLIP tokenizer's
// golden file exercises, reimplemented from ftfy's documented behaviour:
//   - the text is fixed in segments ending after each '\n'; HTML entities are decoded (ftfy's
//     unescape_html) only until a segment containing '<' has been seen ("auto" mode);
//   - each segment is fixed repeatedly until nothing changes:
//       unescape_html, remove_terminal_escapes (ESC [ digits/';' letter),
//       fix_encoding: UTF-8 mojibake read as windows-1252/latin-1 ("cafÃ©" -> "café"), then C1
//         controls U+0080..U+009F decoded as windows-1252,
//       fix_latin_ligatures (ﬁ -> fi, ...), fix_character_width (U+FF01..U+FFEF by NFKC, U+3000 ->
//         space), uncurl_quotes (U+02BC, U+2018..U+201B -> ', U+201C..U+201F -> "),
//       fix_line_breaks (\r\n, \r, U+2028, U+2029, U+0085 -> \n), remove_control_chars
//         (U+0000-0008, 000B, 000E-001F, 007F, 206A-206F, FEFF, FFF9-FFFC), NFC.
// Not reproduced: ftfy's statistical "badness" gate for fix_encoding (here any well-formed
// multi-byte UTF-8 sequence spelled in windows-1252/latin-1 characters is re-decoded, which can
// only misfire on text that genuinely contains such letter+symbol runs, e.g. "Ã©"), the
// encodings other than UTF-8-as-windows-1252/latin-1 (MacRoman, cp437, ...), restore_byte_a0
// and replace_lossy_sequences.
#include <string>

namespace cls::clip {

std::u32string ftfy_fix_text(const std::u32string& text);

}  // namespace cls::clip
