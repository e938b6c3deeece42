#pragma once
// Results sent to rank 0 as bytes: trivially copyable values and strings appended in order and
// read back in the same order (every rank runs the same binary, so no byte-order questions).
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace raycast::cli::distributed {

template <class T>
void put(std::string& bytes, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

inline void put_string(std::string& bytes, const std::string& text) {
  put(bytes, text.size());
  bytes += text;
}

class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    need(sizeof value);
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::string get_string() {
    const auto size = get<std::size_t>();
    need(size);
    std::string text = bytes_.substr(at_, size);
    at_ += size;
    return text;
  }
  /// The next `size` bytes, in place.
  const char* take(std::size_t size) {
    need(size);
    const char* p = bytes_.data() + at_;
    at_ += size;
    return p;
  }

 private:
  void need(std::size_t size) const {
    if (size > bytes_.size() - at_) throw std::runtime_error("truncated result from a rank");
  }
  const std::string& bytes_;
  std::size_t at_ = 0;
};

}  // namespace raycast::cli::distributed
