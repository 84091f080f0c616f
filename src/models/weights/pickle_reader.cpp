#include "models/weights/pickle_reader.h"

#include <cerrno>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <map>

#include "core/error.h"

namespace cls {
namespace {

using Kind = PyValue::Kind;

PyRef make(Kind k) {
  auto v = std::make_shared<PyValue>();
  v->kind = k;
  return v;
}
PyRef make_int(int64_t i) {
  auto v = make(Kind::Int);
  v->i = i;
  return v;
}
PyRef make_str(Kind k, std::string s) {
  auto v = make(k);
  v->s = std::move(s);
  return v;
}

// torch.<X>Storage -> element type (torch.UntypedStorage holds bytes).
bool storage_dtype(const std::string& global, at::ScalarType* out) {
  static const std::map<std::string, at::ScalarType> kTypes = {
      {"torch.FloatStorage", at::kFloat},   {"torch.HalfStorage", at::kHalf},   {"torch.BFloat16Storage", at::kBFloat16},
      {"torch.DoubleStorage", at::kDouble}, {"torch.LongStorage", at::kLong},   {"torch.IntStorage", at::kInt},
      {"torch.ShortStorage", at::kShort},   {"torch.CharStorage", at::kChar},   {"torch.ByteStorage", at::kByte},
      {"torch.BoolStorage", at::kBool},     {"torch.UntypedStorage", at::kByte}};
  const auto it = kTypes.find(global);
  if (it == kTypes.end()) return false;
  *out = it->second;
  return true;
}

class Machine {
 public:
  Machine(const std::string& b, const std::string& name) : b_(b), name_(name) {}

  PyRef run() {
    while (true) {
      const uint8_t op = u8();
      switch (op) {
        case 0x80: u8(); break;                       // PROTO
        case 0x95: take(8); break;                    // FRAME
        case '(': marks_.push_back(stack_.size()); break;
        case '.': return pop();                       // STOP
        case ')': push(make(Kind::Tuple)); break;
        case 't': { auto t = make(Kind::Tuple); t->items = pop_mark(); push(t); break; }
        case 0x85: case 0x86: case 0x87: {            // TUPLE1..3
          const size_t n = op - 0x84u;
          need_stack(n);
          auto t = make(Kind::Tuple);
          t->items.assign(stack_.end() - static_cast<std::ptrdiff_t>(n), stack_.end());
          stack_.resize(stack_.size() - n);
          push(t);
          break;
        }
        case ']': push(make(Kind::List)); break;
        case 'l': { auto l = make(Kind::List); l->items = pop_mark(); push(l); break; }
        case 'a': { auto v = pop(); append(top(), {v}); break; }
        case 'e': { auto items = pop_mark(); append(top(), items); break; }
        case '}': push(make(Kind::Dict)); break;
        case 'd': { auto d = make(Kind::Dict); set_items(d, pop_mark()); push(d); break; }
        case 's': { auto v = pop(); auto k = pop(); set_items(top(), {k, v}); break; }
        case 'u': { auto items = pop_mark(); set_items(top(), items); break; }
        case 'N': push(make(Kind::None)); break;
        case 0x88: case 0x89: { auto v = make(Kind::Bool); v->i = op == 0x88; push(v); break; }
        case 'J': push(make_int(static_cast<int32_t>(le(4)))); break;
        case 'K': push(make_int(u8())); break;
        case 'M': push(make_int(static_cast<int64_t>(le(2)))); break;
        case 0x8a: push(make_int(long_n(u8()))); break;
        case 0x8b: push(make_int(long_n(le(4)))); break;
        case 'G': {                                   // BINFLOAT, big-endian
          const std::string raw = take(8);
          uint64_t bits = 0;
          for (const char c : raw) bits = bits << 8 | static_cast<uint8_t>(c);
          auto v = make(Kind::Float);
          std::memcpy(&v->f, &bits, 8);
          push(v);
          break;
        }
        case 'X': case 'T': case 'B': push(make_str(Kind::String, take(le(4)))); break;
        case 0x8c: case 'U': case 'C': push(make_str(Kind::String, take(u8()))); break;
        case 0x8d: case 0x8e: push(make_str(Kind::String, take(le(8)))); break;
        case 'c': {                                   // GLOBAL module\nname\n
          const std::string module = line(), cls = line();
          push(make_str(Kind::Global, module + "." + cls));
          break;
        }
        case 0x93: {                                  // STACK_GLOBAL
          auto cls = pop(), module = pop();
          push(make_str(Kind::Global, module->s + "." + cls->s));
          break;
        }
        case 'q': memo_[u8()] = top(); break;
        case 'r': memo_[le(4)] = top(); break;
        case 0x94: memo_[memo_.size()] = top(); break;
        case 'p': memo_[memo_index(line())] = top(); break;
        case 'h': push(memo(u8())); break;
        case 'j': push(memo(le(4))); break;
        case 'g': push(memo(memo_index(line()))); break;
        case '0': pop(); break;
        case '1': pop_mark(); break;
        case '2': push(top()); break;
        case 'R': { auto args = pop(); auto fn = pop(); push(reduce(fn, args)); break; }
        case 0x81: {                                  // NEWOBJ
          auto args = pop(), cls = pop();
          auto obj = make_str(Kind::Object, cls->s);
          obj->items = args->items;
          if (cls->s == "collections.OrderedDict") obj = make(Kind::Dict);
          push(obj);
          break;
        }
        case 'b': { auto state = pop(); build(top(), state); break; }
        case 'Q': push(persistent(pop())); break;
        default: {
          char hex[8];
          std::snprintf(hex, sizeof hex, "0x%02x", op);
          error(std::string("unsupported pickle opcode ") + hex + " at byte " + std::to_string(pos_ - 1));
        }
      }
    }
  }

 private:
  [[noreturn]] void error(const std::string& what) const { fail(name_, "data.pkl: " + what); }

  uint8_t u8() {
    if (pos_ >= b_.size()) error("truncated pickle");
    return static_cast<uint8_t>(b_[pos_++]);
  }
  uint64_t le(int n) {
    uint64_t v = 0;
    for (int k = 0; k < n; ++k) v |= uint64_t(u8()) << (8 * k);
    return v;
  }
  int64_t long_n(uint64_t n) {
    if (n > 8) error("integer wider than 64 bits");
    if (n == 0) return 0;
    uint64_t v = le(static_cast<int>(n));
    if (n < 8 && (v >> (8 * n - 1)) & 1) v |= ~uint64_t(0) << (8 * n);  // sign-extend
    return static_cast<int64_t>(v);
  }
  std::string take(uint64_t n) {
    if (n > b_.size() - pos_) error("truncated pickle");
    std::string s = b_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  // The decimal memo index of PUT / GET (protocol 0).
  uint64_t memo_index(const std::string& text) const {
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0])) || *end != '\0' || errno == ERANGE)
      error("memo index '" + text.substr(0, 40) + "' is not a number");
    return v;
  }
  std::string line() {
    const size_t end = b_.find('\n', pos_);
    if (end == std::string::npos) error("truncated pickle");
    std::string s = b_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return s;
  }
  void push(PyRef v) { stack_.push_back(std::move(v)); }
  void need_stack(size_t n) const {
    if (stack_.size() < n) error("pickle stack underflow");
  }
  PyRef pop() {
    need_stack(1);
    PyRef v = stack_.back();
    stack_.pop_back();
    return v;
  }
  PyRef& top() {
    need_stack(1);
    return stack_.back();
  }
  std::vector<PyRef> pop_mark() {
    if (marks_.empty()) error("pickle MARK missing");
    const size_t m = marks_.back();
    marks_.pop_back();
    if (m > stack_.size()) error("pickle stack underflow below MARK");
    std::vector<PyRef> items(stack_.begin() + static_cast<std::ptrdiff_t>(m), stack_.end());
    stack_.resize(m);
    return items;
  }
  PyRef memo(uint64_t k) {
    const auto it = memo_.find(k);
    if (it == memo_.end()) error("pickle memo entry " + std::to_string(k) + " missing");
    return it->second;
  }
  void append(const PyRef& list, const std::vector<PyRef>& items) {
    if (list->kind != Kind::List && list->kind != Kind::Object) error("APPEND to a non-list");
    list->items.insert(list->items.end(), items.begin(), items.end());
  }
  void set_items(const PyRef& d, const std::vector<PyRef>& kv) {
    if (kv.size() % 2) error("odd number of dict items");
    if (d->kind != Kind::Dict && d->kind != Kind::Object) error("SETITEM on a non-dict");
    for (size_t k = 0; k < kv.size(); k += 2) d->dict.emplace_back(kv[k], kv[k + 1]);
  }
  void build(const PyRef& obj, const PyRef& state) {
    if (obj->kind != Kind::Object) return;  // e.g. Parameter state: nothing we need
    if (state->kind == Kind::Dict) {
      obj->dict.insert(obj->dict.end(), state->dict.begin(), state->dict.end());
    } else if (state->kind == Kind::Tuple) {  // (dict, slots) or custom state
      for (const auto& part : state->items)
        if (part->kind == Kind::Dict) obj->dict.insert(obj->dict.end(), part->dict.begin(), part->dict.end());
    } else {
      obj->dict.emplace_back(make_str(Kind::String, "__state__"), state);
    }
  }
  // ('storage', torch.FloatStorage, key, location, numel)
  PyRef persistent(const PyRef& pid) {
    if (pid->kind != Kind::Tuple || pid->items.size() < 5 || pid->items[0]->s != "storage" ||
        pid->items[1]->kind != Kind::Global || pid->items[4]->kind != Kind::Int)
      error("unsupported persistent id (expected a ('storage', type, key, location, numel) tuple)");
    auto st = make_str(Kind::Storage, pid->items[2]->kind == Kind::String ? pid->items[2]->s
                                                                         : std::to_string(pid->items[2]->i));
    if (!storage_dtype(pid->items[1]->s, &st->tensor.dtype)) error("unsupported storage type " + pid->items[1]->s);
    st->tensor.storage_numel = pid->items[4]->i;
    st->tensor.storage_key = st->s;
    return st;
  }
  std::vector<int64_t> ints(const PyRef& t, const char* what) {
    if (t->kind != Kind::Tuple && t->kind != Kind::List) error(std::string(what) + " is not a tuple");
    std::vector<int64_t> out;
    for (const auto& v : t->items) {
      if (v->kind != Kind::Int) error(std::string(what) + " holds a non-integer");
      out.push_back(v->i);
    }
    return out;
  }
  PyRef reduce(const PyRef& fn, const PyRef& args) {
    if (fn->kind != Kind::Global) error("REDUCE of a non-global");
    const std::string& g = fn->s;
    const auto& a = args->items;
    if (g == "collections.OrderedDict" || g == "builtins.dict") return make(Kind::Dict);
    if (g == "torch._utils._rebuild_tensor_v2" || g == "torch._utils._rebuild_tensor") {
      if (a.size() < 4 || a[0]->kind != Kind::Storage || a[1]->kind != Kind::Int)
        error("bad arguments to " + g);
      auto t = make(Kind::Tensor);
      t->tensor = a[0]->tensor;
      t->tensor.offset = a[1]->i;
      t->tensor.sizes = ints(a[2], "tensor size");
      t->tensor.strides = ints(a[3], "tensor stride");
      if (t->tensor.sizes.size() != t->tensor.strides.size()) error("tensor size and stride differ in length");
      return t;
    }
    if (g == "torch._utils._rebuild_parameter" || g == "torch._utils._rebuild_parameter_with_state") {
      if (a.empty()) error("bad arguments to " + g);
      return a[0];
    }
    if (g == "torch._tensor._rebuild_from_type_v2") {  // (func, type, args, state)
      if (a.size() < 3) error("bad arguments to " + g);
      return reduce(a[0], a[2]);
    }
    if (g == "torch.jit._pickle.restore_type_tag") {
      if (a.empty()) error("bad arguments to " + g);
      return a[0];
    }
    if (g.rfind("torch.jit._pickle.build_", 0) == 0) {  // build_intlist, build_tensorlist, ...
      if (a.empty()) error("bad arguments to " + g);
      return a[0];
    }
    // Anything else (argparse.Namespace, numpy scalars, ...) stays an inert object.
    auto obj = make_str(Kind::Object, g);
    obj->items = a;
    return obj;
  }

  const std::string& b_;
  const std::string& name_;
  size_t pos_ = 0;
  std::vector<PyRef> stack_;
  std::vector<size_t> marks_;
  std::map<uint64_t, PyRef> memo_;
};

}  // namespace

PyRef read_pickle(const std::string& bytes, const std::string& name) { return Machine(bytes, name).run(); }

}  // namespace cls
