// The CLIP BPE tokenizer against the reference golden file (openai/CLIP simple_tokenizer.py and
// clip.tokenize, tests/fixtures/clip/tokenizer/README.md): every line's normalised string,
// pre-token pieces, ids and padded ids must be identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/clip/html_unescape.h"
#include "models/clip/tokenizer.h"
#include "models/clip/unicode_text.h"

namespace {

using cls::clip::Tokenizer;

const Tokenizer& tokenizer() {
  static const Tokenizer t(std::string(CLS_TEST_DATA) + "/clip/bpe_simple_vocab_16e6.txt.gz");
  return t;
}

const std::string kGolden = std::string(CLS_TEST_FIXTURES) + "/clip/tokenizer/golden.jsonl";

std::vector<nlohmann::json> golden_lines() {
  std::ifstream in(kGolden);
  std::vector<nlohmann::json> out;
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) out.push_back(nlohmann::json::parse(line));
  return out;
}

TEST(ClipTokenizer, VocabularyLayout) {
  const Tokenizer& t = tokenizer();
  EXPECT_EQ(t.vocab_size(), 49408);
  EXPECT_EQ(t.piece(0), "!");
  EXPECT_EQ(t.piece(64), "a");
  EXPECT_EQ(t.piece(320), "a</w>");
  EXPECT_EQ(t.piece(49406), "<|startoftext|>");
  EXPECT_EQ(t.piece(49407), "<|endoftext|>");
  // Byte 0x20 (space) is one of the 68 non-printable bytes: U+0100 + 32 = 'Ġ'.
  EXPECT_EQ(t.piece(188 + 32), "\xc4\xa0");
}

TEST(ClipTokenizer, GoldenFileEveryLine) {
  const std::vector<nlohmann::json> lines = golden_lines();
  // Every line of the file was read (one JSON object per line).
  const std::string raw = cls::read_text_file(kGolden);
  size_t non_empty = 0;
  for (size_t at = 0; at < raw.size();) {
    const size_t end = std::min(raw.find('\n', at), raw.size());
    non_empty += end > at;
    at = end + 1;
  }
  ASSERT_GT(lines.size(), 0u);
  ASSERT_EQ(lines.size(), non_empty);
  int truncated = 0;
  for (const auto& g : lines) {
    const std::string text = g["text"];
    SCOPED_TRACE("text: " + text);
    // The file's flag is len(ids) + 2 > 77, so every over-long line takes the truncation check below.
    EXPECT_EQ(g["truncated"].get<bool>(), g["ids"].size() + 2 > 77);
    EXPECT_EQ(Tokenizer::normalize(text), g["normalized"].get<std::string>());
    std::vector<std::string> pieces;
    for (const std::string& tok : Tokenizer::pre_tokenize(Tokenizer::normalize(text)))
      for (const std::string& p : tokenizer().bpe_pieces(tok)) pieces.push_back(p);
    EXPECT_EQ(pieces, g["pieces"].get<std::vector<std::string>>());
    EXPECT_EQ(tokenizer().encode(text), g["ids"].get<std::vector<int64_t>>());
    EXPECT_EQ(tokenizer().tokenize(text), g["ids_padded77"].get<std::vector<int64_t>>());
    if (g["truncated"].get<bool>()) {
      ++truncated;
      EXPECT_THROW(tokenizer().tokenize(text, 77, /*truncate=*/false), cls::Error);
    }
  }
  EXPECT_GT(truncated, 0);  // the truncation branch is exercised
}

TEST(ClipTokenizer, BatchIsRowsOfSingleTexts) {
  const std::vector<std::string> texts{"a door", "", "a roof"};
  const std::vector<int64_t> batch = tokenizer().tokenize(texts);
  ASSERT_EQ(batch.size(), 3u * 77u);
  for (size_t r = 0; r < texts.size(); ++r) {
    const std::vector<int64_t> row = tokenizer().tokenize(texts[r]);
    EXPECT_TRUE(std::equal(row.begin(), row.end(), batch.begin() + r * 77)) << r;
  }
  EXPECT_EQ(batch[77], cls::clip::kStartOfText);
  EXPECT_EQ(batch[78], cls::clip::kEndOfText);
}

TEST(ClipTokenizer, MissingOrCorruptVocabularyIsAnError) {
  EXPECT_THROW(Tokenizer("/nonexistent/bpe.txt.gz"), cls::Error);
  // A plain (non-gzip) short file: zlib reads it transparently, and it has too few merges.
  const std::string path = testing::TempDir() + "clip_vocab_short.txt";
  std::ofstream(path) << "version\na b\n";
  EXPECT_THROW(Tokenizer{path}, cls::Error);
}

}  // namespace

namespace {

// Python 3.11 html.unescape on edge cases (expected values printed by CPython's html module).
TEST(ClipHtmlUnescape, MatchesPythonOnEdgeCases) {
  using cls::clip::html_unescape;
  using cls::clip::utf32_to_utf8;
  using cls::clip::utf8_to_utf32;
  auto un = [](const std::string& s) { return utf32_to_utf8(html_unescape(utf8_to_utf32(s))); };
  EXPECT_EQ(un("&copy2024"), "\xc2\xa9" "2024");   // legacy name without ';', longest prefix
  EXPECT_EQ(un("&#x110000;"), "\xef\xbf\xbd");     // beyond U+10FFFF
  EXPECT_EQ(un("&#xD800;"), "\xef\xbf\xbd");       // surrogate
  EXPECT_EQ(un("&#128;"), "\xe2\x82\xac");         // windows-1252 euro
  EXPECT_EQ(un("&#0;"), "\xef\xbf\xbd");
  EXPECT_EQ(un("&#1;"), "");                        // invalid code point dropped
  EXPECT_EQ(un("&amp"), "&");
  EXPECT_EQ(un("&notit;"), "\xc2\xac" "it;");
  EXPECT_EQ(un("&ampx"), "&x");
  EXPECT_EQ(un("&#x;"), "&#x;");
}

TEST(ClipTokenizer, VocabularyIsFoundAndOverridable) {
  EXPECT_TRUE(std::filesystem::exists(cls::clip::default_vocab_path()));
  const std::string path = testing::TempDir() + "clip_vocab_override.gz";
  std::filesystem::copy_file(std::string(CLS_TEST_DATA) + "/clip/bpe_simple_vocab_16e6.txt.gz", path,
                             std::filesystem::copy_options::overwrite_existing);
  setenv("CLS_CLIP_VOCAB", path.c_str(), 1);
  EXPECT_EQ(cls::clip::default_vocab_path(), std::filesystem::path(path));
  unsetenv("CLS_CLIP_VOCAB");
}

}  // namespace
