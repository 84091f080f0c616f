#include "models/weights/safetensors.h"

#include <ATen/ATen.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"

namespace cls {
namespace {

// A read-only view of a whole file, mapped copy-on-write so a caller writing into a zero-copy
// tensor changes only its private pages, never the file.
class MappedFile {
 public:
  explicit MappedFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail(path, std::string("cannot open weight file: ") + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
      ::close(fd);
      fail(path, "cannot stat weight file");
    }
    size_ = static_cast<size_t>(st.st_size);
    if (size_ > 0) {
      void* p = ::mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_PRIVATE, fd, 0);
      if (p == MAP_FAILED) {
        ::close(fd);
        fail(path, std::string("cannot mmap weight file: ") + std::strerror(errno));
      }
      data_ = static_cast<uint8_t*>(p);
    }
    ::close(fd);
  }
  ~MappedFile() {
    if (data_) ::munmap(data_, size_);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  uint8_t* data() const { return data_; }
  size_t size() const { return size_; }

 private:
  uint8_t* data_ = nullptr;
  size_t size_ = 0;
};

const std::map<std::string, at::ScalarType>& dtype_table() {
  static const std::map<std::string, at::ScalarType> t = {
      {"F64", at::kDouble}, {"F32", at::kFloat}, {"F16", at::kHalf}, {"BF16", at::kBFloat16},
      {"I64", at::kLong},   {"I32", at::kInt},   {"I16", at::kShort}, {"I8", at::kChar},
      {"U8", at::kByte},    {"BOOL", at::kBool}};
  return t;
}

constexpr uint64_t kMaxHeader = 100u << 20;  // the reference implementation's limit (100 MB)

struct Span {
  std::string name;
  uint64_t begin, end;
};

}  // namespace

at::ScalarType safetensors_dtype(const std::string& name) {
  const auto it = dtype_table().find(name);
  if (it == dtype_table().end()) throw Error("unsupported safetensors dtype '" + name + "'");
  return it->second;
}

std::string safetensors_dtype_name(at::ScalarType t) {
  for (const auto& [name, type] : dtype_table())
    if (type == t) return name;
  throw Error(std::string("no safetensors dtype for ") + c10::toString(t));
}

WeightFile read_safetensors(const std::string& path) {
  auto file = std::make_shared<MappedFile>(path);
  const size_t size = file->size();
  if (size < 8) fail(path, "not a safetensors file (" + std::to_string(size) + " bytes, shorter than the 8-byte header size)");
  uint64_t header_len = 0;
  for (int k = 0; k < 8; ++k) header_len |= uint64_t(file->data()[k]) << (8 * k);
  if (header_len > kMaxHeader || header_len > size - 8)
    fail(path, "not a safetensors file or truncated: header size " + std::to_string(header_len) +
                   " exceeds the file (" + std::to_string(size) + " bytes)");
  const char* header_begin = reinterpret_cast<const char*>(file->data() + 8);
  if (header_len == 0 || header_begin[0] != '{') fail(path, "not a safetensors file: header is not a JSON object");
  nlohmann::json header;
  try {
    header = nlohmann::json::parse(header_begin, header_begin + header_len);
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("bad safetensors header JSON: ") + e.what());
  }
  if (!header.is_object()) fail(path, "bad safetensors header: not a JSON object");

  const uint64_t buffer_offset = 8 + header_len;
  const uint64_t buffer_size = size - buffer_offset;
  WeightFile out(path);
  std::vector<Span> spans;
  for (const auto& [name, desc] : header.items()) {
    if (name == "__metadata__") {
      if (!desc.is_object()) fail(path, "__metadata__ is not an object");
      for (const auto& [k, v] : desc.items()) {
        if (!v.is_string()) fail(path, "__metadata__ value '" + k + "' is not a string");
        out.metadata[k] = v.get<std::string>();
      }
      continue;
    }
    const std::string where = "tensor '" + name + "': ";
    if (!desc.is_object() || !desc.contains("dtype") || !desc.contains("shape") || !desc.contains("data_offsets"))
      fail(path, where + "entry needs dtype, shape and data_offsets");
    if (!desc["dtype"].is_string()) fail(path, where + "dtype is not a string");
    TensorInfo info;
    try {
      info.dtype = safetensors_dtype(desc["dtype"].get<std::string>());
    } catch (const Error& e) {
      fail(path, where + e.what());
    }
    const auto& shape = desc["shape"];
    const auto& offsets = desc["data_offsets"];
    if (!shape.is_array()) fail(path, where + "shape is not an array");
    uint64_t numel = 1;
    bool overflow = false;
    for (const auto& d : shape) {
      if (!d.is_number_unsigned()) fail(path, where + "shape entries must be non-negative integers");
      const uint64_t v = d.get<uint64_t>();
      if (v != 0 && numel > (uint64_t{1} << 62) / v) overflow = true;
      numel *= v;
      info.shape.push_back(static_cast<int64_t>(v));
    }
    if (!offsets.is_array() || offsets.size() != 2 || !offsets[0].is_number_unsigned() ||
        !offsets[1].is_number_unsigned())
      fail(path, where + "data_offsets must be two non-negative integers");
    const uint64_t begin = offsets[0].get<uint64_t>(), end = offsets[1].get<uint64_t>();
    if (end < begin) fail(path, where + "data_offsets end before they begin");
    if (end > buffer_size)
      fail(path, where + "data [" + std::to_string(begin) + ", " + std::to_string(end) +
                     ") lies beyond the end of the file's data (" + std::to_string(buffer_size) +
                     " bytes): truncated file?");
    const uint64_t item = c10::elementSize(info.dtype);
    if (overflow || numel * item != end - begin)
      fail(path, where + desc["dtype"].get<std::string>() + " " + shape_string(info.shape) + " needs " +
                     (overflow ? std::string("too many") : std::to_string(numel * item)) + " bytes, data_offsets give " +
                     std::to_string(end - begin));
    spans.push_back({name, begin, end});

    uint8_t* ptr = file->data() + buffer_offset + begin;
    out.add(name, info, [file, ptr, info, item]() -> at::Tensor {
      const auto options = at::TensorOptions().dtype(info.dtype);
      if (reinterpret_cast<uintptr_t>(ptr) % item == 0) {
        // Zero-copy: the tensor keeps the mapping alive.
        return at::from_blob(ptr, info.shape, [file](void*) {}, options);
      }
      at::Tensor t = at::empty(info.shape, options);
      if (t.numel()) std::memcpy(t.data_ptr(), ptr, static_cast<size_t>(t.numel()) * item);
      return t;
    });
  }
  // The buffer must be indexed completely, without overlaps or holes (as the reference checks).
  std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) {
    return a.begin != b.begin ? a.begin < b.begin : a.end < b.end;
  });
  uint64_t covered = 0;
  for (const Span& s : spans) {
    if (s.begin < covered) fail(path, "tensor '" + s.name + "': data overlaps the previous tensor's");
    if (s.begin > covered)
      fail(path, "tensor '" + s.name + "': hole of " + std::to_string(s.begin - covered) + " bytes before its data");
    covered = s.end;
  }
  if (covered != buffer_size)
    fail(path, std::to_string(buffer_size - covered) + " bytes after the last tensor's data are not indexed by the header");
  return out;
}

void write_safetensors(const std::string& path, const std::vector<SafetensorsEntry>& entries,
                       const std::map<std::string, std::string>& metadata) {
  // nlohmann::ordered_json keeps the entries in file order.
  nlohmann::ordered_json header;
  if (!metadata.empty()) header["__metadata__"] = metadata;
  uint64_t offset = 0;
  std::vector<at::Tensor> blobs;
  for (const auto& e : entries) {
    uint64_t numel = 1;
    for (const int64_t d : e.shape) numel *= static_cast<uint64_t>(d);
    const uint64_t bytes = numel * c10::elementSize(e.dtype);
    at::Tensor blob;
    if (e.data.defined()) {
      blob = e.data.detach().to(at::kCPU).to(e.dtype).contiguous();
      if (std::vector<int64_t>(blob.sizes().begin(), blob.sizes().end()) != e.shape)
        fail(path, "write_safetensors: tensor '" + e.name + "' has shape " +
                       shape_string(std::vector<int64_t>(blob.sizes().begin(), blob.sizes().end())) +
                       ", entry says " + shape_string(e.shape));
    }
    blobs.push_back(blob);
    header[e.name] = {{"dtype", safetensors_dtype_name(e.dtype)},
                      {"shape", e.shape},
                      {"data_offsets", {offset, offset + bytes}}};
    offset += bytes;
  }
  std::string json = header.dump();
  json.append((8 - json.size() % 8) % 8, ' ');  // the data starts 8-byte aligned
  write_atomic(path, [&](const std::filesystem::path& tmp) {
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail(path, "cannot create file");
    auto write_all = [&](const void* p, size_t n, uint64_t at) {
      const char* c = static_cast<const char*>(p);
      while (n > 0) {
        const ssize_t w = ::pwrite(fd, c, n, static_cast<off_t>(at));
        if (w <= 0) {
          ::close(fd);
          fail(path, "write failed");
        }
        c += w;
        n -= static_cast<size_t>(w);
        at += static_cast<uint64_t>(w);
      }
    };
    uint8_t len[8];
    for (int k = 0; k < 8; ++k) len[k] = static_cast<uint8_t>((uint64_t(json.size()) >> (8 * k)) & 0xff);
    write_all(len, 8, 0);
    write_all(json.data(), json.size(), 8);
    const uint64_t base = 8 + json.size();
    uint64_t at_offset = 0;
    for (size_t i = 0; i < entries.size(); ++i) {
      const uint64_t bytes = static_cast<uint64_t>(blobs[i].defined() ? blobs[i].numel() * blobs[i].element_size() : 0);
      if (blobs[i].defined() && bytes) write_all(blobs[i].data_ptr(), bytes, base + at_offset);
      uint64_t numel = 1;
      for (const int64_t d : entries[i].shape) numel *= static_cast<uint64_t>(d);
      at_offset += numel * c10::elementSize(entries[i].dtype);
    }
    if (::ftruncate(fd, static_cast<off_t>(base + offset)) != 0) {
      ::close(fd);
      fail(path, "cannot extend file");
    }
    if (::close(fd) != 0) fail(path, "close failed");
  });
}

}  // namespace cls
