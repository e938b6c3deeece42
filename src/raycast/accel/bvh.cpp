#include "accel/bvh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

namespace raycast {

namespace {

constexpr int kMaxBins = 64;
// Below this depth splits follow the SAH; deeper nodes split at the object median, which adds at
// most log2(2^32) = 32 levels, so trees stay shallower than the traversal stacks (bvh_traverse.h).
constexpr std::uint32_t kMaxSahDepth = 64;

struct Bin {
  Aabb box;
  std::uint32_t count = 0;
};

// A primitive's box and centre, moved together with its index by the partition so that every
// pass over a node reads memory in order (gathering boxes through the permutation made the upper
// levels of the build wait on cache misses).
struct PrimRef {
  Aabb box;
  Vec3 centre;
};

class Builder {
 public:
  Builder(std::span<const Aabb> boxes, std::span<const Vec3> centres, const BvhBuildConfig& c,
          Bvh& out)
      : boxes_(boxes), centres_(centres), config_(c), out_(out) {
    config_.bins = std::clamp(config_.bins, 2, kMaxBins);
    config_.max_leaf_size = std::max(config_.max_leaf_size, 1);
    config_.leaf_block = std::max(config_.leaf_block, 1);
  }

  void run() {
    const std::size_t n = boxes_.size();
    out_.prims.resize(n);
    for (std::size_t i = 0; i < n; ++i) out_.prims[i] = static_cast<std::uint32_t>(i);
    if (n == 0) return;
    refs_.resize(n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      refs_[i] = {boxes_[i], centres_[i]};
    });
    out_.nodes.resize(2 * n - 1);
    next_node_ = 1;
    tbb::task_group tasks;
    Aabb box, centre_box;
    node_bounds(0, static_cast<std::uint32_t>(n), box, centre_box);
    build(0, 0, static_cast<std::uint32_t>(n), 0, box, centre_box, tasks);
    tasks.wait();
    out_.nodes.resize(next_node_.load());
  }

 private:
  // The boxes of a split's two sides, known from the bins and the partition pass, so that
  // children need no pass of their own to find their bounds.
  struct Sides {
    Aabb box[2], centre_box[2];
  };

  // Builds node_index over prims[begin, end), whose box and centre box are given.
  void build(std::uint32_t node_index, std::uint32_t begin, std::uint32_t end, std::uint32_t depth,
             Aabb box, Aabb centre_box, tbb::task_group& tasks) {
    // Iterative on the right child, recursive (or a task) on the left, to bound the stack depth.
    for (;;) {
      BvhNode& node = out_.nodes[node_index];
      node.box = box;
      const std::uint32_t count = end - begin;
      std::uint32_t mid = 0;
      Sides sides;
      const bool leaf = count <= static_cast<std::uint32_t>(config_.min_leaf_size) ||
                        (depth < kMaxSahDepth ? !split(box, centre_box, begin, end, mid, sides)
                                              : !split_median(centre_box, begin, end, mid, sides));
      if (leaf) {
        node.first = begin;
        node.count = count;
        return;
      }
      const std::uint32_t first = next_node_.fetch_add(2);
      node.first = first;
      node.count = 0;
      if (mid - begin >= config_.parallel_threshold) {
        tasks.run([this, first, begin, mid, depth, sides, &tasks] {
          build(first, begin, mid, depth + 1, sides.box[0], sides.centre_box[0], tasks);
        });
      } else {
        build(first, begin, mid, depth + 1, sides.box[0], sides.centre_box[0], tasks);
      }
      ++depth;
      node_index = first + 1;
      begin = mid;
      box = sides.box[1];
      centre_box = sides.centre_box[1];
    }
  }

  using BinSet = std::array<std::array<Bin, kMaxBins>, 3>;

  // Bins prims[begin, end) on all three axes in one pass.
  void bin_range(BinSet& bins, int nbins, const Aabb& centre_box, const Vec3& scale,
                 std::uint32_t begin, std::uint32_t end) const {
    for (std::uint32_t i = begin; i < end; ++i) {
      const PrimRef& ref = refs_[i];
      const Vec3& c = ref.centre;
      for (int axis = 0; axis < 3; ++axis) {
        if (!(scale[axis] > 0)) continue;
        Bin& b = bins[axis][bin_of(c[axis], centre_box.lo[axis], scale[axis], nbins)];
        b.box.grow(ref.box);
        ++b.count;
      }
    }
  }

  double blocks(std::uint32_t count) const {
    return static_cast<double>((count + config_.leaf_block - 1) / config_.leaf_block);
  }

  // The box of prims[begin, end) and the box of their centres (in parallel for large ranges).
  void node_bounds(std::uint32_t begin, std::uint32_t end, Aabb& box, Aabb& centre_box) const {
    using Pair = std::pair<Aabb, Aabb>;
    auto grow = [this](const tbb::blocked_range<std::uint32_t>& r, Pair acc) {
      for (std::uint32_t i = r.begin(); i < r.end(); ++i) {
        acc.first.grow(refs_[i].box);
        acc.second.grow(refs_[i].centre);
      }
      return acc;
    };
    Pair result;
    if (end - begin >= config_.parallel_binning_threshold) {
      result = tbb::parallel_reduce(tbb::blocked_range<std::uint32_t>(begin, end, 8192), Pair{},
                                    grow, [](Pair a, const Pair& b) {
                                      a.first.grow(b.first);
                                      a.second.grow(b.second);
                                      return a;
                                    });
    } else {
      result = grow(tbb::blocked_range<std::uint32_t>(begin, end), Pair{});
    }
    box = result.first;
    centre_box = result.second;
  }

  // Chooses a split by binned SAH and partitions prims[begin, end). Returns false for a leaf.
  bool split(const Aabb& box, const Aabb& centre_box, std::uint32_t begin, std::uint32_t end,
             std::uint32_t& mid, Sides& sides) {
    const std::uint32_t count = end - begin;
    // Small nodes bin into fewer bins (never fewer than 4): the same splits for a fraction of the
    // fixed cost of resetting and sweeping the bins, which dominates below a few dozen primitives.
    const int bins =
        static_cast<int>(std::min<std::uint32_t>(config_.bins, std::max<std::uint32_t>(4, count)));
    double best_cost = kInfinity;
    int best_axis = -1, best_bin = 0;
    const Vec3 extent = centre_box.extent();
    Vec3 scale;
    for (int axis = 0; axis < 3; ++axis) {
      scale[axis] = extent[axis] > 0 ? bins / extent[axis] : 0;
      if (!std::isfinite(scale[axis])) scale[axis] = 0;  // a denormal extent: treat as flat
    }
    // Per-thread scratch bins, reset only as far as used (zeroing all kMaxBins cost more than the
    // binning itself on small nodes).
    static thread_local BinSet scratch;
    BinSet& bin = scratch;
    for (auto& axis_bins : bin)
      for (int b = 0; b < bins; ++b) axis_bins[b] = Bin{};
    if (count >= config_.parallel_binning_threshold) {
      bin = tbb::parallel_reduce(
          tbb::blocked_range<std::uint32_t>(begin, end, 8192), BinSet{},
          [&](const tbb::blocked_range<std::uint32_t>& r, BinSet acc) {
            bin_range(acc, bins, centre_box, scale, r.begin(), r.end());
            return acc;
          },
          [bins](BinSet a, const BinSet& b) {
            for (int axis = 0; axis < 3; ++axis)
              for (int i = 0; i < bins; ++i) {
                a[axis][i].box.grow(b[axis][i].box);
                a[axis][i].count += b[axis][i].count;
              }
            return a;
          });
    } else {
      bin_range(bin, bins, centre_box, scale, begin, end);
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (!(scale[axis] > 0)) continue;
      // Sweep from the right, then from the left, to cost every split plane.
      std::array<double, kMaxBins> right_cost;  // entries 1 .. bins-1 are set below
      Aabb acc;
      std::uint32_t acc_count = 0;
      for (int b = bins - 1; b > 0; --b) {
        acc.grow(bin[axis][b].box);
        acc_count += bin[axis][b].count;
        right_cost[b] = acc.half_area() * blocks(acc_count);
      }
      acc = Aabb{};
      acc_count = 0;
      for (int b = 0; b < bins - 1; ++b) {
        acc.grow(bin[axis][b].box);
        acc_count += bin[axis][b].count;
        const double cost = acc.half_area() * blocks(acc_count) + right_cost[b + 1];
        if (acc_count > 0 && acc_count < count && cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_bin = b + 1;
        }
      }
    }
    const double leaf_cost = blocks(count) * config_.primitive_cost;
    const double area = box.half_area();
    if (best_axis >= 0) {
      const double split_cost =
          config_.traversal_cost + config_.primitive_cost * best_cost / (area > 0 ? area : 1);
      if (split_cost >= leaf_cost && count <= static_cast<std::uint32_t>(config_.max_leaf_size))
        return false;
      const double s = scale[best_axis];
      const double lo = centre_box.lo[best_axis];
      for (int b = 0; b < bins; ++b) sides.box[b < best_bin ? 0 : 1].grow(bin[best_axis][b].box);
      // Hoare partition that grows each side's centre box as it classifies each primitive once.
      auto left = [&](const Vec3& c) { return bin_of(c[best_axis], lo, s, bins) < best_bin; };
      std::uint32_t i = begin, j = end;
      for (;;) {
        while (i < j && left(refs_[i].centre)) sides.centre_box[0].grow(refs_[i++].centre);
        while (i < j && !left(refs_[j - 1].centre)) sides.centre_box[1].grow(refs_[--j].centre);
        if (i >= j) break;
        sides.centre_box[1].grow(refs_[i].centre);
        sides.centre_box[0].grow(refs_[j - 1].centre);
        --j;
        std::swap(out_.prims[i], out_.prims[j]);
        std::swap(refs_[i], refs_[j]);
        ++i;
      }
      mid = i;
      return true;
    }
    // All centres coincide: split by index when the node is too big for a leaf.
    if (count <= static_cast<std::uint32_t>(config_.max_leaf_size)) return false;
    mid = begin + count / 2;
    node_bounds(begin, mid, sides.box[0], sides.centre_box[0]);
    node_bounds(mid, end, sides.box[1], sides.centre_box[1]);
    return true;
  }

  // Splits prims[begin, end) at the median centre along the widest centre axis (by index when
  // all centres coincide), moving the primitive records with their indices. Returns false for a
  // node small enough to be a leaf. Only pathological inputs get this deep, so it may allocate.
  bool split_median(const Aabb& centre_box, std::uint32_t begin, std::uint32_t end,
                    std::uint32_t& mid, Sides& sides) {
    const std::uint32_t count = end - begin;
    if (count <= static_cast<std::uint32_t>(config_.max_leaf_size)) return false;
    const int axis = max_dimension(centre_box.extent());
    mid = begin + count / 2;
    std::vector<std::uint32_t> order(count);
    for (std::uint32_t k = 0; k < count; ++k) order[k] = begin + k;
    std::nth_element(order.begin(), order.begin() + (mid - begin), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                       return refs_[a].centre[axis] < refs_[b].centre[axis];
                     });
    std::vector<PrimRef> refs(count);
    std::vector<std::uint32_t> prims(count);
    for (std::uint32_t k = 0; k < count; ++k) {
      refs[k] = refs_[order[k]];
      prims[k] = out_.prims[order[k]];
    }
    std::copy(refs.begin(), refs.end(), refs_.begin() + begin);
    std::copy(prims.begin(), prims.end(), out_.prims.begin() + begin);
    node_bounds(begin, mid, sides.box[0], sides.centre_box[0]);
    node_bounds(mid, end, sides.box[1], sides.centre_box[1]);
    return true;
  }

  static int bin_of(double c, double lo, double scale, int bins) {
    const int b = static_cast<int>((c - lo) * scale);
    return std::clamp(b, 0, bins - 1);
  }

  std::span<const Aabb> boxes_;
  std::span<const Vec3> centres_;
  std::vector<PrimRef> refs_;  // refs_[i] belongs to out_.prims[i]
  BvhBuildConfig config_;
  Bvh& out_;
  std::atomic<std::uint32_t> next_node_{0};
};

}  // namespace

Bvh build_bvh(std::span<const Aabb> boxes, std::span<const Vec3> centres,
              const BvhBuildConfig& config) {
  Bvh bvh;
  Builder(boxes, centres, config, bvh).run();
  return bvh;
}

}  // namespace raycast
