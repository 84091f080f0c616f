#pragma once
// CLIP's byte-level BPE tokenizer, behaving byte-for-byte like openai/CLIP
// clip/simple_tokenizer.py (SimpleTokenizer) and clip.tokenize (d05afc4):
//   normalise: ftfy.fix_text (see ftfy_fixes.h), html.unescape twice, strip, collapse
//     whitespace runs to one space, strip, str.lower();
//   pre-tokenise with the reference pattern (IGNORECASE)
//     <\|startoftext\|>|<\|endoftext\|>|'s|'t|'re|'ve|'m|'ll|'d|[\p{L}]+|[\p{N}]|[^\s\p{L}\p{N}]+
//     (implemented by hand: at each position the alternatives in this order, else skip a char);
//   BPE over bytes_to_unicode() symbols with '</w>' on the last symbol, merges by rank;
//   tokenize(): 49406, ids..., 49407, 0-padding to the context length; with truncation the
//     first `context` ids are kept and the last becomes 49407.
// The vocabulary is bpe_simple_vocab_16e6.txt.gz (MIT, openai/CLIP), shipped in data/clip/.
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

namespace cls::clip {

constexpr int64_t kStartOfText = 49406;
constexpr int64_t kEndOfText = 49407;
constexpr int kContextLength = 77;

// Where the vocabulary is looked for, first hit wins: the environment variable
// CLS_CLIP_VOCAB (a file), <dir of the running binary>/data/clip/, <dir>/../share/citylangsplat/
// clip/, then <source tree>/data/clip/. Throws cls::Error listing the places tried.
std::filesystem::path default_vocab_path();

class Tokenizer {
 public:
  // Reads the gzip'ed merges file; throws cls::Error naming the file when it is missing/corrupt.
  explicit Tokenizer(const std::filesystem::path& vocab_gz = default_vocab_path());

  // SimpleTokenizer.encode: BPE ids without start/end tokens, never truncated.
  std::vector<int64_t> encode(const std::string& utf8_text) const;
  // clip.tokenize for one text: exactly `context` ids. Without truncation an over-long text is a
  // cls::Error (like the reference's RuntimeError).
  std::vector<int64_t> tokenize(const std::string& utf8_text, int context = kContextLength,
                                bool truncate = true) const;
  // Batch: row-major [texts.size(), context].
  std::vector<int64_t> tokenize(const std::vector<std::string>& texts, int context = kContextLength,
                                bool truncate = true) const;

  // whitespace_clean(basic_clean(text)).lower(): the string the pre-tokeniser sees.
  static std::string normalize(const std::string& utf8_text);
  // The pre-tokens of a normalised text (UTF-8).
  static std::vector<std::string> pre_tokenize(const std::string& normalized_utf8);
  // BPE pieces of one pre-token, in the bytes_to_unicode alphabet ("photo</w>").
  std::vector<std::string> bpe_pieces(const std::string& pre_token_utf8) const;

  int64_t vocab_size() const { return static_cast<int64_t>(decoder_.size()); }
  const std::string& piece(int64_t id) const { return decoder_.at(static_cast<size_t>(id)); }

 private:
  std::vector<std::string> bpe(const std::string& symbols) const;

  std::vector<std::string> byte_symbol_;                 // byte -> its symbol (UTF-8)
  std::unordered_map<std::string, int64_t> encoder_;     // piece -> id
  std::vector<std::string> decoder_;                     // id -> piece
  std::unordered_map<std::string, int> merge_rank_;      // "first second" -> rank
  mutable std::mutex cache_mutex_;
  mutable std::unordered_map<std::string, std::vector<std::string>> cache_;  // BPE results
};

}  // namespace cls::clip
