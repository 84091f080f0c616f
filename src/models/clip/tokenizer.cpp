#include "models/clip/tokenizer.h"

#include <zlib.h>

#include <climits>
#include <cstdlib>
#include <sstream>

#include "core/error.h"
#include "models/clip/ftfy_fixes.h"
#include "models/clip/html_unescape.h"
#include "models/clip/unicode_text.h"

namespace cls::clip {
namespace fs = std::filesystem;

namespace {

constexpr const char* kVocabName = "bpe_simple_vocab_16e6.txt.gz";
// simple_tokenizer.py: merges = lines[1:49152-256-2+1].
constexpr int kMerges = 49152 - 256 - 2;

// bytes_to_unicode(): printable bytes map to themselves, the other 68 to U+0100 + n, in byte order.
// Returns the byte order of the vocabulary (printable bytes first) and each byte's code point.
void bytes_to_unicode(std::vector<int>& order, std::vector<char32_t>& code) {
  code.assign(256, 0);
  order.clear();
  auto printable = [](int b) { return (b >= '!' && b <= '~') || (b >= 0xA1 && b <= 0xAC) || (b >= 0xAE); };
  for (int b = 0; b < 256; ++b)
    if (printable(b)) { order.push_back(b); code[b] = static_cast<char32_t>(b); }
  int n = 0;
  for (int b = 0; b < 256; ++b)
    if (!printable(b)) { order.push_back(b); code[b] = static_cast<char32_t>(256 + n++); }
}

std::string read_gzip(const fs::path& path) {
  gzFile f = gzopen(path.c_str(), "rb");
  if (!f) fail(path.string(), "cannot open the CLIP BPE vocabulary");
  std::string out;
  char buf[1 << 16];
  for (;;) {
    const int n = gzread(f, buf, sizeof buf);
    if (n < 0) {
      int err = 0;
      const std::string msg = gzerror(f, &err);
      gzclose(f);
      fail(path.string(), "corrupt gzip data: " + msg);
    }
    if (n == 0) break;
    out.append(buf, static_cast<size_t>(n));
  }
  gzclose(f);
  return out;
}

bool ends_symbol_run(char32_t c) { return is_space(c) || is_letter(c) || is_number(c); }

// Python str.strip() for the whitespace the reference strips.
std::u32string strip(const std::u32string& s) {
  size_t b = 0, e = s.size();
  while (b < e && is_space(s[b])) ++b;
  while (e > b && is_space(s[e - 1])) --e;
  return s.substr(b, e - b);
}

bool starts_with(const std::u32string& s, size_t pos, const std::u32string& p) {
  return s.compare(pos, p.size(), p) == 0;
}

// 's|'t|'re|'ve|'m|'ll|'d under IGNORECASE (simple case folding: ſ matches s). Length or 0.
size_t contraction_length(const std::u32string& s, size_t i) {
  if (s[i] != U'\'' || i + 1 >= s.size()) return 0;
  auto fold = [](char32_t c) -> char32_t {
    if (c >= 'A' && c <= 'Z') return c - 'A' + 'a';
    if (c == 0x17F) return U's';
    return c;
  };
  const char32_t a = fold(s[i + 1]);
  if (a == U's' || a == U't' || a == U'm' || a == U'd') return 2;
  if (i + 2 < s.size()) {
    const char32_t b = fold(s[i + 2]);
    if ((a == U'r' && b == U'e') || (a == U'v' && b == U'e') || (a == U'l' && b == U'l')) return 3;
  }
  return 0;
}

}  // namespace

fs::path default_vocab_path() {
  std::vector<fs::path> tried;
  if (const char* env = std::getenv("CLS_CLIP_VOCAB"); env && *env) {
    if (fs::exists(env)) return env;
    tried.emplace_back(env);
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    for (const fs::path& p : {exe.parent_path() / "data" / "clip" / kVocabName,
                              exe.parent_path() / ".." / "share" / "citylangsplat" / "clip" / kVocabName}) {
      if (fs::exists(p)) return p;
      tried.push_back(p);
    }
  }
  const fs::path src = fs::path(CLS_SOURCE_DIR) / "data" / "clip" / kVocabName;
  if (fs::exists(src)) return src;
  tried.push_back(src);
  std::string msg = "the CLIP BPE vocabulary " + std::string(kVocabName) +
                    " was not found (set CLS_CLIP_VOCAB to its path); looked at:";
  for (const auto& p : tried) msg += "\n  " + p.string();
  throw Error(msg);
}

Tokenizer::Tokenizer(const fs::path& vocab_gz) {
  const std::string text = read_gzip(vocab_gz);
  std::vector<std::string> lines;
  {
    size_t pos = 0;
    while (pos <= text.size()) {
      size_t e = text.find('\n', pos);
      if (e == std::string::npos) e = text.size();
      lines.push_back(text.substr(pos, e - pos));
      pos = e + 1;
    }
  }
  if (lines.size() < static_cast<size_t>(kMerges) + 1)
    fail(vocab_gz.string(), "has " + std::to_string(lines.size()) + " lines; a CLIP vocabulary has at least " +
                                std::to_string(kMerges + 1));

  std::vector<int> order;
  std::vector<char32_t> code;
  bytes_to_unicode(order, code);
  byte_symbol_.resize(256);
  for (int b = 0; b < 256; ++b) {
    std::string s;
    append_utf8(s, code[b]);
    byte_symbol_[b] = s;
  }
  for (int b : order) decoder_.push_back(byte_symbol_[b]);
  for (int b : order) decoder_.push_back(byte_symbol_[b] + "</w>");
  for (int m = 0; m < kMerges; ++m) {
    const std::string& line = lines[1 + m];
    std::istringstream in(line);
    std::string first, second, extra;
    if (!(in >> first >> second) || (in >> extra))
      fail(vocab_gz.string(), "line " + std::to_string(m + 2) + " is not a merge of two symbols: '" + line + "'");
    merge_rank_[first + " " + second] = m;  // bpe_ranks = dict(zip(merges, ...)): the last rank wins
    decoder_.push_back(first + second);
  }
  decoder_.push_back("<|startoftext|>");
  decoder_.push_back("<|endoftext|>");
  // encoder = dict(zip(vocab, range(len(vocab)))): a later duplicate overrides an earlier one.
  for (size_t id = 0; id < decoder_.size(); ++id) encoder_[decoder_[id]] = static_cast<int64_t>(id);
  cache_["<|startoftext|>"] = {"<|startoftext|>"};
  cache_["<|endoftext|>"] = {"<|endoftext|>"};
}

std::string Tokenizer::normalize(const std::string& utf8_text) {
  // basic_clean: ftfy.fix_text, html.unescape(html.unescape(.)), strip.
  std::u32string t = ftfy_fix_text(utf8_to_utf32(utf8_text));
  t = strip(html_unescape(html_unescape(t)));
  // whitespace_clean: re.sub(r'\s+', ' ', text).strip().
  std::u32string w;
  w.reserve(t.size());
  for (size_t i = 0; i < t.size();) {
    if (is_space(t[i])) {
      w.push_back(U' ');
      while (i < t.size() && is_space(t[i])) ++i;
    } else {
      w.push_back(t[i++]);
    }
  }
  return utf32_to_utf8(to_lower(strip(w)));
}

std::vector<std::string> Tokenizer::pre_tokenize(const std::string& normalized_utf8) {
  static const std::u32string kSot = U"<|startoftext|>", kEot = U"<|endoftext|>";
  const std::u32string s = utf8_to_utf32(normalized_utf8);
  std::vector<std::string> out;
  size_t i = 0;
  while (i < s.size()) {
    size_t len = 0;
    if (starts_with(s, i, kSot)) len = kSot.size();
    else if (starts_with(s, i, kEot)) len = kEot.size();
    else if ((len = contraction_length(s, i)) > 0) {}
    else if (is_letter(s[i])) { len = 1; while (i + len < s.size() && is_letter(s[i + len])) ++len; }
    else if (is_number(s[i])) len = 1;
    else if (!is_space(s[i])) {
      len = 1;
      while (i + len < s.size() && !ends_symbol_run(s[i + len])) ++len;
    }
    if (len == 0) { ++i; continue; }  // whitespace: findall skips it
    out.push_back(utf32_to_utf8(s.substr(i, len)));
    i += len;
  }
  return out;
}

std::vector<std::string> Tokenizer::bpe(const std::string& token) const {
  {
    std::lock_guard<std::mutex> lock(cache_mutex_);
    auto it = cache_.find(token);
    if (it != cache_.end()) return it->second;
  }
  // The token is a string of byte symbols (each one UTF-8 character of 1-2 bytes).
  std::vector<std::string> word;
  for (size_t i = 0; i < token.size();) {
    const unsigned char c = token[i];
    const size_t n = c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
    word.push_back(token.substr(i, n));
    i += n;
  }
  word.back() += "</w>";
  while (word.size() > 1) {
    int best = INT_MAX;
    std::string first, second;
    for (size_t i = 0; i + 1 < word.size(); ++i) {
      auto it = merge_rank_.find(word[i] + " " + word[i + 1]);
      if (it != merge_rank_.end() && it->second < best) {
        best = it->second;
        first = word[i];
        second = word[i + 1];
      }
    }
    if (best == INT_MAX) break;
    std::vector<std::string> merged;
    merged.reserve(word.size());
    for (size_t i = 0; i < word.size();) {
      if (i + 1 < word.size() && word[i] == first && word[i + 1] == second) {
        merged.push_back(first + second);
        i += 2;
      } else {
        merged.push_back(word[i++]);
      }
    }
    word.swap(merged);
  }
  std::lock_guard<std::mutex> lock(cache_mutex_);
  cache_.emplace(token, word);
  return word;
}

std::vector<std::string> Tokenizer::bpe_pieces(const std::string& pre_token_utf8) const {
  std::string symbols;
  for (unsigned char b : pre_token_utf8) symbols += byte_symbol_[b];
  return bpe(symbols);
}

std::vector<int64_t> Tokenizer::encode(const std::string& utf8_text) const {
  std::vector<int64_t> ids;
  for (const std::string& token : pre_tokenize(normalize(utf8_text))) {
    for (const std::string& p : bpe_pieces(token)) {
      auto it = encoder_.find(p);
      if (it == encoder_.end()) throw Error("CLIP tokenizer: BPE piece '" + p + "' is not in the vocabulary");
      ids.push_back(it->second);
    }
  }
  return ids;
}

std::vector<int64_t> Tokenizer::tokenize(const std::string& utf8_text, int context, bool truncate) const {
  if (context < 2) throw Error("CLIP tokenizer: context length must be at least 2");
  std::vector<int64_t> ids{kStartOfText};
  const std::vector<int64_t> body = encode(utf8_text);
  ids.insert(ids.end(), body.begin(), body.end());
  ids.push_back(kEndOfText);
  if (ids.size() > static_cast<size_t>(context)) {
    if (!truncate)
      throw Error("CLIP tokenizer: input is too long for context length " + std::to_string(context) +
                  " (" + std::to_string(ids.size()) + " tokens): \"" + utf8_text.substr(0, 60) + "\"");
    ids.resize(static_cast<size_t>(context));
    ids.back() = kEndOfText;
  }
  ids.resize(static_cast<size_t>(context), 0);
  return ids;
}

std::vector<int64_t> Tokenizer::tokenize(const std::vector<std::string>& texts, int context,
                                         bool truncate) const {
  std::vector<int64_t> out;
  out.reserve(texts.size() * static_cast<size_t>(context));
  for (const std::string& t : texts) {
    const std::vector<int64_t> row = tokenize(t, context, truncate);
    out.insert(out.end(), row.begin(), row.end());
  }
  return out;
}

}  // namespace cls::clip
