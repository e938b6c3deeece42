#pragma once
// Intervals of a ray's whole line inside a solid, the currency of CSG and `cast --all`.
#include <cstddef>
#include <memory>

#include "geometry/hit.h"

namespace raycast {

/// One interval [in.t, out.t] along the line; in.t may be -inf and out.t +inf for unbounded
/// solids (those ends have part == kNoSurface). Each end carries what `surface` needs.
/// An open surface's crossing is a zero-length span with in == out.
struct Span {
  LocalHit in;
  LocalHit out;
};

/// A small vector of spans, sorted by increasing t and disjoint (touching allowed) when produced
/// by shapes and by CSG. Inline storage for the common case; grows on the heap past it.
class SpanList {
 public:
  static constexpr std::size_t kInline = 8;

  SpanList() = default;
  SpanList(const SpanList& o) { *this = o; }
  SpanList& operator=(const SpanList& o) {
    if (this != &o) {
      clear();
      for (const Span& s : o) push_back(s);
    }
    return *this;
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() { size_ = 0; }
  Span* begin() { return data(); }
  Span* end() { return data() + size_; }
  const Span* begin() const { return data(); }
  const Span* end() const { return data() + size_; }
  Span& operator[](std::size_t i) { return data()[i]; }
  const Span& operator[](std::size_t i) const { return data()[i]; }
  Span& back() { return data()[size_ - 1]; }

  void push_back(const Span& s) {
    if (size_ == capacity_) grow();
    data()[size_++] = s;
  }
  void add(const LocalHit& in, const LocalHit& out) { push_back({in, out}); }

 private:
  Span* data() { return heap_ ? heap_.get() : inline_; }
  const Span* data() const { return heap_ ? heap_.get() : inline_; }
  void grow() {
    const std::size_t cap = capacity_ * 2;
    auto bigger = std::make_unique<Span[]>(cap);
    for (std::size_t i = 0; i < size_; ++i) bigger[i] = data()[i];
    heap_ = std::move(bigger);
    capacity_ = cap;
  }

  Span inline_[kInline];
  std::unique_ptr<Span[]> heap_;
  std::size_t size_ = 0;
  std::size_t capacity_ = kInline;
};

}  // namespace raycast
