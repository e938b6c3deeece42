#include "load/did_you_mean.h"

#include <algorithm>

namespace raycast {

int edit_distance(std::string_view a, std::string_view b) {
  // Three rows of the dynamic-programming table: two back (for swaps), one back, this one.
  const std::size_t n = b.size();
  std::vector<int> before(n + 1), prev(n + 1), cur(n + 1);
  for (std::size_t j = 0; j <= n; ++j) prev[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= n; ++j) {
      const int substitute = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, substitute});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        cur[j] = std::min(cur[j], before[j - 2] + 1);
    }
    std::swap(before, prev);
    std::swap(prev, cur);
  }
  return prev[n];
}

std::string nearest_name(std::string_view word, const std::vector<std::string>& candidates) {
  constexpr int kMaxEdits = 2;  // beyond two edits a "suggestion" is mostly noise
  std::string best;
  int best_distance = kMaxEdits + 1;
  for (const std::string& c : candidates) {
    if (c == word) continue;
    const int d = edit_distance(word, c);
    if (d < best_distance && d < static_cast<int>(word.size())) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string best = nearest_name(word, candidates);
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

}  // namespace raycast
