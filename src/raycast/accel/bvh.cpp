#include "accel/bvh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include "accel/build_memory.h"
#include "io/progress.h"

namespace raycast {

namespace {

// Four float lanes as a GCC/Clang vector (SSE on x86-64, NEON on Arm); lane 3 is ignored.
using F4 = float __attribute__((vector_size(16)));
using I4 = std::int32_t __attribute__((vector_size(16)));

constexpr int kMaxBins = 32;
// Below this depth splits follow the SAH; deeper nodes split at the object median, which adds at
// most log2(2^32) = 32 levels, so trees stay shallower than the traversal stacks (bvh_traverse.h).
constexpr std::uint32_t kMaxSahDepth = 64;
// Large nodes partition in chunks of this many references (a fixed size, so that the result does
// not depend on the number of threads).
constexpr std::uint32_t kChunk = 16384;

constexpr float kInf = std::numeric_limits<float>::infinity();

// Lane 3 of the low corner holds the index's bits, a denormal float for small indices:
// arithmetic on it would take the slow denormal path, so it is cleared on load.
inline F4 load_lo(const BvhBuildRef& r) {
  I4 v;
  std::memcpy(&v, r.lo, 16);
  v &= I4{-1, -1, -1, 0};
  F4 f;
  std::memcpy(&f, &v, 16);
  return f;
}
inline F4 load_hi(const BvhBuildRef& r) {
  F4 v;
  std::memcpy(&v, r.hi, 16);
  return v;
}
inline F4 vmin(F4 a, F4 b) { return a < b ? a : b; }
inline F4 vmax(F4 a, F4 b) { return a > b ? a : b; }
inline F4 splat(float x) { return F4{x, x, x, x}; }

// A box in float lanes (x, y, z, unused), empty by default.
struct Box4 {
  F4 lo = splat(kInf);
  F4 hi = splat(-kInf);
  void grow(F4 l, F4 h) {
    lo = vmin(lo, l);
    hi = vmax(hi, h);
  }
  void grow(const Box4& b) { grow(b.lo, b.hi); }
  void grow_point(F4 p) { grow(p, p); }
  // Half the surface area; 0 when empty.
  float half_area() const {
    const F4 e = hi - lo;
    if (!(e[0] >= 0 && e[1] >= 0 && e[2] >= 0)) return 0;
    return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
  }
};

// A reference's centre, doubled (lo + hi: exact for the clamped range, no rounding of a halving).
inline F4 centre2(const BvhBuildRef& r) { return load_lo(r) + load_hi(r); }

using FNode = BvhFloatNode;

struct Bins {
  Box4 box[3][kMaxBins];
  std::uint32_t count[3][kMaxBins];
  void reset(int bins) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < bins; ++b) {
        box[a][b] = Box4{};
        count[a][b] = 0;
      }
  }
  void merge(const Bins& o, int bins) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < bins; ++b) {
        box[a][b].grow(o.box[a][b]);
        count[a][b] += o.count[a][b];
      }
  }
};

// Maps doubled centres to bins: (c - lo) * scale, clamped to [0, bins - 1] (NaN to 0), truncated.
// The same arithmetic classifies references for binning and for the partition, so that both agree.
struct Binner {
  F4 lo;
  F4 scale;  // 0 on an axis whose centres all coincide
  F4 top;    // bins - 1
  I4 operator()(F4 c) const {
    F4 b = (c - lo) * scale;
    b = b > 0 ? b : splat(0);  // NaN compares false: bin 0
    b = b < top ? b : top;
    return __builtin_convertvector(b, I4);
  }
};

float round_down(double x) {
  if (!(x > -kBuildRefLimit)) return -kBuildRefLimit;
  if (x >= kBuildRefLimit) return kBuildRefLimit;
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -kInf);
  return f;
}

float round_up(double x) {
  if (!(x < kBuildRefLimit)) return kBuildRefLimit;
  if (x <= -kBuildRefLimit) return -kBuildRefLimit;
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, kInf);
  return f;
}

double widen_lo(float x) { return x <= -kBuildRefLimit ? -kInfinity : x; }
double widen_hi(float x) { return x >= kBuildRefLimit ? kInfinity : x; }

class Builder {
 public:
  Builder(BvhBuildRefs& refs, const BvhBuildConfig& c)
      : refs_(refs), config_(c), progress_("building BVH", refs.size()) {
    config_.bins = std::clamp(config_.bins, 2, kMaxBins);
    config_.max_leaf_size = std::max(config_.max_leaf_size, 1);
    config_.leaf_block = std::max(config_.leaf_block, 1);
  }

  FloatBvh run() {
    FloatBvh out;
    const std::size_t n = refs_.size();
    if (n == 0) return out;
    if (n >= 0x7FFFFFFFu) throw std::length_error("BVH build: too many primitives");
    // Up to 2n - 1 nodes, left uninitialised: the buffer is not touched beyond the nodes made, so
    // the pages of the unused tail are never committed.
    out.nodes.resize(2 * n - 1);
    nodes_ = out.nodes.data();
    next_node_ = 1;
    Box4 box, centres;
    bounds(0, static_cast<std::uint32_t>(n), box, centres);
    tbb::task_group tasks;
    build(0, 0, static_cast<std::uint32_t>(n), 0, box, centres, tasks);
    tasks.wait();
    progress_.finish();
    out.nodes.resize(next_node_.load());
    out.prims.resize(n);  // uninitialised: written in parallel below
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16384),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i < r.end(); ++i)
                          out.prims[i] = refs_[i].index;
                      });
    return out;
  }

 private:
  struct Sides {
    Box4 box[2], centres[2];
  };

  bool big(std::uint32_t count) const { return count >= config_.parallel_binning_threshold; }

  // Builds node_index over refs[begin, end), whose box and doubled-centre box are given.
  void build(std::uint32_t node_index, std::uint32_t begin, std::uint32_t end, std::uint32_t depth,
             Box4 box, Box4 centres, tbb::task_group& tasks) {
    // Iterative on the right child, recursive (or a task) on the left, to bound the stack depth.
    for (;;) {
      FNode& node = nodes_[node_index];
      for (int a = 0; a < 3; ++a) {
        node.lo[a] = box.lo[a];
        node.hi[a] = box.hi[a];
      }
      const std::uint32_t count = end - begin;
      std::uint32_t mid = 0;
      Sides sides;
      const bool leaf = count <= static_cast<std::uint32_t>(config_.min_leaf_size) ||
                        (depth < kMaxSahDepth ? !split(box, centres, begin, end, mid, sides)
                                              : !split_median(centres, begin, end, mid, sides));
      if (leaf) {
        node.first = begin;
        node.count = count;
        progress_.advance(count);
        return;
      }
      const std::uint32_t first = next_node_.fetch_add(2);
      node.first = first;
      node.count = 0;
      if (mid - begin >= config_.parallel_threshold) {
        tasks.run([this, first, begin, mid, depth, sides, &tasks] {
          build(first, begin, mid, depth + 1, sides.box[0], sides.centres[0], tasks);
        });
      } else {
        build(first, begin, mid, depth + 1, sides.box[0], sides.centres[0], tasks);
      }
      ++depth;
      node_index = first + 1;
      begin = mid;
      box = sides.box[1];
      centres = sides.centres[1];
    }
  }

  // The box and the doubled-centre box of refs[begin, end) (in parallel for large ranges).
  void bounds(std::uint32_t begin, std::uint32_t end, Box4& box, Box4& centres) const {
    using Pair = std::pair<Box4, Box4>;
    auto grow = [this](const tbb::blocked_range<std::uint32_t>& r, Pair acc) {
      for (std::uint32_t i = r.begin(); i < r.end(); ++i) {
        const F4 lo = load_lo(refs_[i]), hi = load_hi(refs_[i]);
        acc.first.grow(lo, hi);
        acc.second.grow_point(lo + hi);
      }
      return acc;
    };
    Pair result;
    if (big(end - begin)) {
      result = tbb::parallel_reduce(tbb::blocked_range<std::uint32_t>(begin, end, kChunk), Pair{},
                                    grow, [](Pair a, const Pair& b) {
                                      a.first.grow(b.first);
                                      a.second.grow(b.second);
                                      return a;
                                    });
    } else {
      result = grow(tbb::blocked_range<std::uint32_t>(begin, end), Pair{});
    }
    box = result.first;
    centres = result.second;
  }

  // Bins refs[begin, end) into `bins`. Long ranges alternate between `bins` and `other` (merged
  // into `bins` at the end): consecutive references of a coherent mesh often fall into the same
  // bins, and one set would chain every update on the previous one through memory.
  __attribute__((noinline)) void bin_range(Bins& bins, Bins& other, int nbins, const Binner& binner,
                                           std::uint32_t begin, std::uint32_t end) const {
    const Binner bn = binner;
    const BvhBuildRef* const refs = refs_.data();
    auto add = [&](Bins& into, const BvhBuildRef& ref) {
      const F4 lo = load_lo(ref), hi = load_hi(ref);
      const I4 b = bn(lo + hi);
      for (int a = 0; a < 3; ++a) {
        into.box[a][b[a]].grow(lo, hi);
        ++into.count[a][b[a]];
      }
    };
    if (end - begin < 256) {
      for (std::uint32_t i = begin; i < end; ++i) add(bins, refs[i]);
      return;
    }
    other.reset(nbins);
    std::uint32_t i = begin;
    for (; i + 1 < end; i += 2) {
      __builtin_prefetch(refs + i + 16);
      add(bins, refs[i]);
      add(other, refs[i + 1]);
    }
    if (i < end) add(bins, refs[i]);
    bins.merge(other, nbins);
  }

  std::uint32_t blocks(std::uint32_t count) const {
    return (count + config_.leaf_block - 1) / config_.leaf_block;
  }

  // Chooses a split by binned SAH and partitions refs[begin, end). Returns false for a leaf.
  bool split(const Box4& box, const Box4& centres, std::uint32_t begin, std::uint32_t end,
             std::uint32_t& mid, Sides& sides) {
    const std::uint32_t count = end - begin;
    // Small nodes bin into fewer bins (never fewer than 4): the same splits for a fraction of the
    // fixed cost of resetting and sweeping the bins, which dominates below a few dozen primitives.
    const int nbins =
        static_cast<int>(std::min<std::uint32_t>(config_.bins, std::max<std::uint32_t>(4, count)));
    Binner binner;
    binner.lo = centres.lo;
    binner.top = splat(static_cast<float>(nbins - 1));
    const F4 extent = centres.hi - centres.lo;
    bool any_axis = false;
    for (int a = 0; a < 3; ++a) {
      float s = extent[a] > 0 ? static_cast<float>(nbins) / extent[a] : 0;
      if (!std::isfinite(s)) s = 0;  // a denormal extent: treat the axis as flat
      binner.scale[a] = s;
      any_axis |= s > 0;
    }
    binner.scale[3] = 0;
    if (!any_axis) return split_coincident(begin, end, mid, sides);
    // Small nodes bin into per-thread scratch bins. Large ones get their own: a thread waiting
    // in the parallel binning may run another node's build, which would reuse the scratch.
    static thread_local Bins scratch;
    std::unique_ptr<Bins> own;
    Bins* bins_ptr = &scratch;
    if (big(count)) {
      // The bins are unions and sums, so the result does not depend on how the range is divided.
      auto bin_chunk = [&](const tbb::blocked_range<std::uint32_t>& r, Bins* acc) {
        if (!acc) {
          acc = new Bins;
          acc->reset(nbins);
        }
        Bins other;
        bin_range(*acc, other, nbins, binner, r.begin(), r.end());
        return acc;
      };
      Bins* total =
          tbb::parallel_reduce(tbb::blocked_range<std::uint32_t>(begin, end, kChunk),
                               static_cast<Bins*>(nullptr), bin_chunk, [nbins](Bins* a, Bins* b) {
                                 if (!a) return b;
                                 if (!b) return a;
                                 a->merge(*b, nbins);
                                 delete b;
                                 return a;
                               });
      own.reset(total);
      bins_ptr = total;
    } else {
      static thread_local Bins other;
      scratch.reset(nbins);
      bin_range(scratch, other, nbins, binner, begin, end);
    }
    const Bins& bins = *bins_ptr;
    // Sweep each axis from the right, then from the left, to cost every plane between bins.
    float best_cost = kInf;
    int best_axis = -1, best_bin = 0;
    for (int a = 0; a < 3; ++a) {
      if (!(binner.scale[a] > 0)) continue;
      std::array<float, kMaxBins> right_cost;  // entries 1 .. nbins-1 are set below
      Box4 acc;
      std::uint32_t acc_count = 0;
      for (int b = nbins - 1; b > 0; --b) {
        acc.grow(bins.box[a][b]);
        acc_count += bins.count[a][b];
        right_cost[b] = acc.half_area() * static_cast<float>(blocks(acc_count));
      }
      acc = Box4{};
      acc_count = 0;
      for (int b = 0; b < nbins - 1; ++b) {
        acc.grow(bins.box[a][b]);
        acc_count += bins.count[a][b];
        const float cost =
            acc.half_area() * static_cast<float>(blocks(acc_count)) + right_cost[b + 1];
        if (acc_count > 0 && acc_count < count && cost < best_cost) {
          best_cost = cost;
          best_axis = a;
          best_bin = b + 1;
        }
      }
    }
    if (best_axis < 0) {
      // Every plane leaves one side empty or costs infinity (boxes at the clamp limit).
      if (count <= static_cast<std::uint32_t>(config_.max_leaf_size)) return false;
      return split_median(centres, begin, end, mid, sides);
    }
    const double leaf_cost = blocks(count) * config_.primitive_cost;
    const double area = box.half_area();
    const double split_cost =
        config_.traversal_cost + config_.primitive_cost * best_cost / (area > 0 ? area : 1);
    if (split_cost >= leaf_cost && count <= static_cast<std::uint32_t>(config_.max_leaf_size))
      return false;
    for (int b = 0; b < nbins; ++b) sides.box[b < best_bin ? 0 : 1].grow(bins.box[best_axis][b]);
    std::uint32_t left_count = 0;
    for (int b = 0; b < best_bin; ++b) left_count += bins.count[best_axis][b];
    if (big(count))
      partition_parallel(binner, best_axis, best_bin, begin, end, sides);
    else
      partition_serial(binner, best_axis, best_bin, begin, end, sides);
    mid = begin + left_count;
    return true;
  }

  // Hoare partition of refs[begin, end) by bin; grows each side's centre box as it classifies.
  // Returns the number on the left.
  __attribute__((noinline)) std::uint32_t partition_serial(const Binner& binner, int axis,
                                                           int split_bin, std::uint32_t begin,
                                                           std::uint32_t end, Sides& sides) {
    const Binner bn = binner;  // a local copy: the swaps below cannot alias it
    BvhBuildRef* const refs = refs_.data();
    auto left = [&](F4 c) { return bn(c)[axis] < split_bin; };
    std::uint32_t i = begin, j = end;
    Box4 cl = sides.centres[0], cr = sides.centres[1];
    for (;;) {
      F4 c;
      while (i < j && left(c = centre2(refs[i]))) {
        __builtin_prefetch(refs + i + 16);
        cl.grow_point(c);
        ++i;
      }
      while (i < j && !left(c = centre2(refs[j - 1]))) {
        __builtin_prefetch(refs + j - 16);
        cr.grow_point(c);
        --j;
      }
      if (i >= j) break;
      cr.grow_point(centre2(refs[i]));
      cl.grow_point(centre2(refs[j - 1]));
      --j;
      std::swap(refs[i], refs[j]);
      ++i;
    }
    sides.centres[0] = cl;
    sides.centres[1] = cr;
    return i - begin;
  }

  // The same in parallel: fixed-size chunks partition themselves, then the references on the
  // wrong side of the split point are swapped pairwise (k-th misplaced right with k-th misplaced
  // left). Both steps depend only on the chunking, never on the threads.
  void partition_parallel(const Binner& binner, int axis, int split_bin, std::uint32_t begin,
                          std::uint32_t end, Sides& sides) {
    const std::uint32_t chunks = (end - begin + kChunk - 1) / kChunk;
    std::vector<std::uint32_t> lefts(chunks);
    std::vector<Sides> chunk_sides(chunks);
    tbb::parallel_for(std::uint32_t(0), chunks, [&](std::uint32_t c) {
      const std::uint32_t b = begin + c * kChunk, e = std::min(end, b + kChunk);
      lefts[c] = partition_serial(binner, axis, split_bin, b, e, chunk_sides[c]);
    });
    std::uint32_t total_left = 0;
    for (std::uint32_t c = 0; c < chunks; ++c) {
      total_left += lefts[c];
      sides.centres[0].grow(chunk_sides[c].centres[0]);
      sides.centres[1].grow(chunk_sides[c].centres[1]);
    }
    const std::uint32_t mid = begin + total_left;
    // Misplaced ranges in order: rights in [begin, mid), lefts in [mid, end).
    struct Range {
      std::uint32_t begin, end;
    };
    std::vector<Range> wrong_right, wrong_left;
    for (std::uint32_t c = 0; c < chunks; ++c) {
      const std::uint32_t b = begin + c * kChunk, e = std::min(end, b + kChunk), m = b + lefts[c];
      if (m < std::min(e, mid)) wrong_right.push_back({m, std::min(e, mid)});
      if (m > std::max(b, mid)) wrong_left.push_back({std::max(b, mid), m});
    }
    // Prefix sums of the ranges' lengths, to find the k-th misplaced reference of each kind.
    auto prefix = [](const std::vector<Range>& ranges) {
      std::vector<std::uint64_t> p(ranges.size() + 1, 0);
      for (std::size_t i = 0; i < ranges.size(); ++i)
        p[i + 1] = p[i] + (ranges[i].end - ranges[i].begin);
      return p;
    };
    const std::vector<std::uint64_t> pr = prefix(wrong_right), pl = prefix(wrong_left);
    const std::uint64_t misplaced = pr.back();  // equals pl.back()
    auto locate = [](const std::vector<std::uint64_t>& p, std::uint64_t k) {
      return static_cast<std::size_t>(std::upper_bound(p.begin(), p.end(), k) - p.begin() - 1);
    };
    tbb::parallel_for(
        tbb::blocked_range<std::uint64_t>(0, misplaced, kChunk),
        [&](const tbb::blocked_range<std::uint64_t>& r) {
          std::size_t ir = locate(pr, r.begin()), il = locate(pl, r.begin());
          std::uint32_t xr = wrong_right[ir].begin + static_cast<std::uint32_t>(r.begin() - pr[ir]);
          std::uint32_t xl = wrong_left[il].begin + static_cast<std::uint32_t>(r.begin() - pl[il]);
          for (std::uint64_t k = r.begin(); k < r.end(); ++k) {
            if (xr == wrong_right[ir].end) xr = wrong_right[++ir].begin;
            if (xl == wrong_left[il].end) xl = wrong_left[++il].begin;
            std::swap(refs_[xr++], refs_[xl++]);
          }
        });
  }

  // All centres coincide: split at the middle index (after ordering by index, so that the split
  // does not depend on how earlier partitions ordered the range) when too big for a leaf.
  bool split_coincident(std::uint32_t begin, std::uint32_t end, std::uint32_t& mid, Sides& sides) {
    const std::uint32_t count = end - begin;
    if (count <= static_cast<std::uint32_t>(config_.max_leaf_size)) return false;
    mid = begin + count / 2;
    std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                     [](const BvhBuildRef& a, const BvhBuildRef& b) { return a.index < b.index; });
    bounds(begin, mid, sides.box[0], sides.centres[0]);
    bounds(mid, end, sides.box[1], sides.centres[1]);
    return true;
  }

  // Splits refs[begin, end) at the median centre along the widest centre axis (ties broken by
  // index). Returns false for a node small enough to be a leaf. Only pathological inputs get
  // here, far below the parallel levels.
  bool split_median(const Box4& centres, std::uint32_t begin, std::uint32_t end, std::uint32_t& mid,
                    Sides& sides) {
    const std::uint32_t count = end - begin;
    if (count <= static_cast<std::uint32_t>(config_.max_leaf_size)) return false;
    const F4 e = centres.hi - centres.lo;
    const int axis = e[0] >= e[1] && e[0] >= e[2] ? 0 : (e[1] >= e[2] ? 1 : 2);
    mid = begin + count / 2;
    std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                     [axis](const BvhBuildRef& a, const BvhBuildRef& b) {
                       const float ca = a.lo[axis] + a.hi[axis], cb = b.lo[axis] + b.hi[axis];
                       return ca < cb || (ca == cb && a.index < b.index);
                     });
    bounds(begin, mid, sides.box[0], sides.centres[0]);
    bounds(mid, end, sides.box[1], sides.centres[1]);
    return true;
  }

  BvhBuildRefs& refs_;
  BvhBuildConfig config_;
  FNode* nodes_ = nullptr;
  std::atomic<std::uint32_t> next_node_{0};
  StageProgress progress_;  // drawn for a million primitives or more, on a terminal
};

}  // namespace

BvhBuildRef make_build_ref(const Aabb& box, std::uint32_t index) {
  BvhBuildRef r;
  for (int a = 0; a < 3; ++a) {
    r.lo[a] = round_down(box.lo[a]);
    r.hi[a] = round_up(box.hi[a]);
  }
  r.index = index;
  r.unused = 0;
  return r;
}

FloatBvh build_float_bvh_from_refs(BvhBuildRefs refs, const BvhBuildConfig& config) {
  return Builder(refs, config).run();
}

Bvh build_bvh_from_refs(BvhBuildRefs refs, const BvhBuildConfig& config) {
  FloatBvh f = build_float_bvh_from_refs(std::move(refs), config);
  Bvh out;
  const std::size_t count = f.nodes.size();
  out.nodes.resize(count);  // uninitialised: written in parallel below
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 16384),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i) {
                        const FNode& n = f.nodes[i];
                        BvhNode& b = out.nodes[i];
                        b.box.lo = {widen_lo(n.lo[0]), widen_lo(n.lo[1]), widen_lo(n.lo[2])};
                        b.box.hi = {widen_hi(n.hi[0]), widen_hi(n.hi[1]), widen_hi(n.hi[2])};
                        b.first = n.first;
                        b.count = n.count;
                      }
                    });
  out.prims = std::move(f.prims);
  return out;
}

Bvh build_bvh(std::span<const Aabb> boxes, const BvhBuildConfig& config) {
  BvhBuildRefs refs(boxes.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, boxes.size(), 16384),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i)
                        refs[i] = make_build_ref(boxes[i], static_cast<std::uint32_t>(i));
                    });
  return build_bvh_from_refs(std::move(refs), config);
}

double sah_cost(const Bvh& bvh, const BvhBuildConfig& config) {
  if (bvh.empty()) return 0;
  const double root = bvh.nodes[0].box.half_area();
  const int block = std::max(config.leaf_block, 1);
  // Summed in depth-first order, so that the figure does not depend on node numbering.
  double cost = 0;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const BvhNode& n = bvh.nodes[stack.back()];
    stack.pop_back();
    const double area = n.box.half_area();
    if (n.is_leaf()) {
      cost += config.primitive_cost * ((n.count + block - 1) / block) * area;
    } else {
      cost += config.traversal_cost * area;
      stack.push_back(n.first + 1);
      stack.push_back(n.first);
    }
  }
  return root > 0 ? cost / root : cost;
}

}  // namespace raycast
