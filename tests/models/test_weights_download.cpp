#include <gtest/gtest.h>

#include "models/temp_dir.h"
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "models/model_registry.h"
#include "models/weights/download.h"
#include "models/weights/safetensors.h"
#include "models/weights/sam_weights.h"
#include "models/weights/sha256.h"

namespace fs = std::filesystem;
using namespace cls;
using test::TempDir;
using test::write_bytes;

namespace {

std::string payload() {
  std::string s(300000, '\0');
  uint32_t x = 12345;
  for (char& c : s) c = static_cast<char>((x = x * 1103515245u + 12345u) >> 24);
  return s;
}

std::string file_url(const fs::path& p) { return "file://" + fs::absolute(p).string(); }

// No test touches the network: every source is a file:// URL.
struct Isolated {
  TempDir dir;
  Isolated() {
    ::setenv("XDG_CACHE_HOME", (dir.path / "xdg").c_str(), 1);
    ::unsetenv("CITYLANGSPLAT_MODELS");
  }
};

}  // namespace

// FIPS 180-4 / NIST test vectors.
TEST(Sha256, KnownVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // Chunked updates give the same digest as one update.
  const std::string p = payload();
  Sha256 s;
  for (size_t i = 0; i < p.size(); i += 777) s.update(p.substr(i, 777));
  EXPECT_EQ(s.hex_digest(), sha256_hex(p));
}

TEST(Download, FetchesVerifiesAndSkipsPresentFiles) {
  Isolated iso;
  const std::string data = payload();
  write_bytes(iso.dir.path / "src.bin", data);
  DownloadRequest r{file_url(iso.dir.path / "src.bin"), iso.dir.path / "cache" / "m.bin", data.size(), sha256_hex(data), "m", false};
  const DownloadResult a = download_file(r);
  EXPECT_FALSE(a.already_present);
  EXPECT_EQ(a.bytes, data.size());
  EXPECT_EQ(read_text_file(r.dest), data);
  EXPECT_FALSE(fs::exists(r.dest.string() + ".part"));
  const DownloadResult b = download_file(r);  // second run: verified, nothing fetched
  EXPECT_TRUE(b.already_present);
  // A present file with the wrong content is reported, not silently replaced.
  write_bytes(r.dest, "tampered");
  EXPECT_THROW(download_file(r), Error);
}

TEST(Download, ResumesFromAPartFile) {
  Isolated iso;
  const std::string data = payload();
  write_bytes(iso.dir.path / "src.bin", data);
  const fs::path dest = iso.dir.path / "cache" / "m.bin";
  fs::create_directories(dest.parent_path());
  write_bytes(dest.string() + ".part", data.substr(0, 123457));  // an interrupted earlier run
  const DownloadResult r = download_file({file_url(iso.dir.path / "src.bin"), dest, data.size(), sha256_hex(data), "m", false});
  EXPECT_EQ(r.resumed_from, 123457u);
  EXPECT_EQ(read_text_file(dest), data);
  // A part file that is not a prefix of the source fails the checksum and is removed.
  fs::remove(dest);
  write_bytes(dest.string() + ".part", std::string(1000, 'x'));
  try {
    download_file({file_url(iso.dir.path / "src.bin"), dest, data.size(), sha256_hex(data), "m", false});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("checksum mismatch"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dest.string() + ".part"));
  EXPECT_FALSE(fs::exists(dest));
  // ... so the next run starts over and succeeds.
  EXPECT_EQ(download_file({file_url(iso.dir.path / "src.bin"), dest, data.size(), sha256_hex(data), "m", false}).bytes,
            data.size());
}

TEST(Download, SizeMismatchAndUnreachableSources) {
  Isolated iso;
  const std::string data = payload();
  write_bytes(iso.dir.path / "src.bin", data);
  const fs::path dest = iso.dir.path / "cache" / "m.bin";
  try {
    download_file({file_url(iso.dir.path / "src.bin"), dest, data.size() + 10, "", "m", false});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("expected " + std::to_string(data.size() + 10)), std::string::npos) << e.what();
  }
  fs::remove(dest.string() + ".part");
  EXPECT_THROW(download_file({file_url(iso.dir.path / "missing.bin"), dest, 0, "", "m", false}), DownloadError);
  EXPECT_FALSE(fs::exists(dest));
  EXPECT_FALSE(fs::exists(dest.string() + ".part"));
  // Without a published checksum the file is accepted and its sha256 reported.
  EXPECT_EQ(download_file({file_url(iso.dir.path / "src.bin"), dest, 0, "", "m", false}).sha256, sha256_hex(data));
}

TEST(ModelRegistry, NamesDirectoriesAndLookup) {
  Isolated iso;
  EXPECT_EQ(find_known_model("sam-vit-h")->file_name, "sam_vit_h_4b8939.pth");
  EXPECT_EQ(find_known_model("vit_h")->name, "sam-vit-h");
  EXPECT_EQ(find_known_model("SAM_VIT_B")->arch, "vit_b");
  EXPECT_EQ(find_known_model("openai-clip-vit-b-16")->arch, "ViT-B-16");
  EXPECT_EQ(find_known_model("nope"), nullptr);
  for (const auto& m : known_models()) {  // the OpenAI URL names the file's sha256
    if (m.url.find("openaipublic") != std::string::npos) EXPECT_NE(m.url.find(m.sha256), std::string::npos);
    EXPECT_TRUE(m.sha256.empty() || m.sha256.size() == 64) << m.name;
  }
  ::setenv("CITYLANGSPLAT_MODELS", (iso.dir.path / "env").c_str(), 1);
  const auto dirs = model_search_dirs((iso.dir.path / "opt").string());
  ASSERT_EQ(dirs.size(), 3u);
  EXPECT_EQ(dirs[0], iso.dir.path / "opt");
  EXPECT_EQ(dirs[1], iso.dir.path / "env");
  EXPECT_EQ(dirs[2], iso.dir.path / "xdg" / "citylangsplat" / "models");
  fs::create_directories(dirs[1]);
  write_bytes(dirs[1] / "sam_vit_b_01ec64.pth", "x");
  EXPECT_EQ(find_model_file(*find_known_model("sam-vit-b"), dirs), dirs[1] / "sam_vit_b_01ec64.pth");
  EXPECT_FALSE(find_model_file(*find_known_model("sam-vit-h"), dirs).has_value());
  ::unsetenv("CITYLANGSPLAT_MODELS");
}

TEST(ModelsCli, ListShowsWhatIsPresent) {
  Isolated iso;
  fs::create_directories(iso.dir.path / "m");
  write_bytes(iso.dir.path / "m" / "sam_vit_h_4b8939.pth", "x");
  const auto r = test::run_cli("models list --json --models-dir '" + (iso.dir.path / "m").string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["search_dirs"][0], (iso.dir.path / "m").string());
  EXPECT_EQ(j["search_dirs"][1], (iso.dir.path / "xdg" / "citylangsplat" / "models").string());
  int present = 0;
  for (const auto& m : j["models"]) {
    if (m["present"].get<bool>()) {
      ++present;
      EXPECT_EQ(m["name"], "sam-vit-h");
    }
  }
  EXPECT_EQ(present, 1);
  EXPECT_EQ(j["models"].size(), known_models().size());
  const auto text = test::run_cli("models list --models-dir '" + (iso.dir.path / "m").string() + "'");
  EXPECT_NE(text.out.find("sam-vit-h                  present"), std::string::npos) << text.out;
}

// Offline (here: an unreadable mirror) the error says where to put a manually downloaded file.
TEST(ModelsCli, DownloadOfflineSaysWhereToPutTheFile) {
  Isolated iso;
  const auto r = test::run_cli("models download sam-vit-b --no-progress --mirror file:///nonexistent-cls-mirror");
  EXPECT_NE(r.status, 0);
  const fs::path where = iso.dir.path / "xdg" / "citylangsplat" / "models" / "sam_vit_b_01ec64.pth";
  EXPECT_NE(r.err.find("put it at " + where.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("https://dl.fbaipublicfiles.com/segment_anything/sam_vit_b_01ec64.pth"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--models-dir"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ec2df62732614e57411cdcf32a23ffdf28910380d03139ee0f4fcbe91eb8c912"), std::string::npos) << r.err;
  // A mirror serving a file with the wrong content: the checksum check rejects it.
  fs::create_directories(iso.dir.path / "mirror");
  write_bytes(iso.dir.path / "mirror" / "sam_vit_b_01ec64.pth", std::string(375042383 % 1000, 'x'));
  const auto bad = test::run_cli("models download vit_b --no-progress --models-dir '" + (iso.dir.path / "d").string() +
                                 "' --mirror " + file_url(iso.dir.path / "mirror"));
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("expected 375042383"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(iso.dir.path / "d" / "sam_vit_b_01ec64.pth"));
  const auto unknown = test::run_cli("models download sam-vit-x");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("known: openclip-vit-b-16-laion2b"), std::string::npos) << unknown.err;
}

TEST(ModelsCli, CheckReportsLayoutProblems) {
  Isolated iso;
  std::vector<SafetensorsEntry> e;
  for (const auto& t : sam_expected_tensors(sam_arch("vit_b"))) e.push_back({t.name, at::kHalf, t.shape, {}});
  write_safetensors((iso.dir.path / "b.safetensors").string(), e);
  const auto ok = test::run_cli("models check '" + (iso.dir.path / "b.safetensors").string() + "' --model sam-vit-b");
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.out.find("314 tensors match SAM vit_b"), std::string::npos) << ok.out;
  const auto bad = test::run_cli("models check '" + (iso.dir.path / "b.safetensors").string() + "' --model vit_l");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("weights do not match SAM vit_l"), std::string::npos) << bad.err;
}
