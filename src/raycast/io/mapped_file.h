#pragma once
// A read-only memory map of a whole file, for the binary mesh readers: one pass over the bytes
// with no copy, and pages already decoded handed back so they do not count towards peak memory.
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/mesh_file.h"

namespace raycast {

class MappedFile {
 public:
  /// Maps `path` (an empty file maps to nothing); throws MeshFileError when it cannot.
  explicit MappedFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw MeshFileError("cannot open the mesh file");
    struct stat st;
    if (::fstat(fd, &st) != 0) {
      ::close(fd);
      throw MeshFileError("cannot read the mesh file");
    }
    size_ = static_cast<std::size_t>(st.st_size);
    if (size_ > 0) {
      void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
      if (p == MAP_FAILED) {
        ::close(fd);
        throw MeshFileError("cannot map the mesh file");
      }
      data_ = static_cast<const char*>(p);
      ::madvise(p, size_, MADV_SEQUENTIAL);
    }
    ::close(fd);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile() {
    if (data_) ::munmap(const_cast<char*>(data_), size_);
  }
  const char* data() const { return data_; }
  std::size_t size() const { return size_; }
  std::string_view view() const { return {data_, size_}; }
  /// Drops the pages of [p, p + bytes) from the process (they stay in the page cache): a part
  /// already decoded need not count towards the peak memory.
  void release(const char* p, std::size_t bytes) const {
    const std::uintptr_t page = 4096;
    const auto b = (reinterpret_cast<std::uintptr_t>(p) + page - 1) & ~(page - 1);
    const auto e = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(page - 1);
    if (e > b) ::madvise(reinterpret_cast<void*>(b), e - b, MADV_DONTNEED);
  }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace raycast
