// The loader against mutated scene files: every scenes/*.yaml, mutated a few thousand times with a
// fixed seed (a character deleted, a line duplicated, a number swapped for -1, 0, 1e308, .nan,
// .inf, a huge integer or an empty string, deep nesting inserted, ...). Each must either load or
// throw a positioned SceneError; never another exception, a crash or a hang.
// RAYCAST_MUTATIONS overrides the number of mutations per file.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "io/scene_error.h"
#include "load/loader.h"

namespace raycast {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int kDefaultMutations = 60;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int kDefaultMutations = 60;
#else
constexpr int kDefaultMutations = 400;
#endif
#else
constexpr int kDefaultMutations = 400;
#endif

int mutations_per_file() {
  if (const char* env = std::getenv("RAYCAST_MUTATIONS")) return std::max(1, std::atoi(env));
  return kDefaultMutations;
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::vector<std::string> kReplacements = {
    "-1",         "0",          "1e308",       "-1e308",
    ".nan",       ".inf",       "-.inf",       "99999999999999999999999",
    "4294967297", "2147483648", "-2147483649", "\"\"",
    "''",         "1e-320",     "[]",          "{}",
    "~",          "nan",        "1e999",       "[1, 2]",
};

// Spans of the text that look like numbers.
std::vector<std::pair<std::size_t, std::size_t>> numbers(const std::string& s) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < s.size();) {
    const bool start = (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '-') &&
                       (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1])));
    if (!start) {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < s.size() &&
           (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.' || s[j] == 'e'))
      ++j;
    if (j > i + (s[i] == '-' ? 1 : 0)) out.emplace_back(i, j - i);
    i = j;
  }
  return out;
}

std::string mutate(std::string s, std::mt19937_64& rng) {
  auto pick = [&](std::size_t n) {
    return static_cast<std::size_t>(rng() % std::max<std::size_t>(n, 1));
  };
  const int rounds = 1 + static_cast<int>(rng() % 3);
  for (int r = 0; r < rounds && !s.empty(); ++r) {
    switch (rng() % 9) {
      case 0:  // delete a character
        s.erase(pick(s.size()), 1);
        break;
      case 1: {  // duplicate a line
        const std::size_t at = s.rfind('\n', pick(s.size()));
        const std::size_t b = at == std::string::npos ? 0 : at + 1;
        const std::size_t e = s.find('\n', b);
        const std::string line =
            s.substr(b, e == std::string::npos ? std::string::npos : e - b + 1);
        s.insert(b, line);
        break;
      }
      case 2:
      case 3:
      case 4: {  // swap a number
        const auto nums = numbers(s);
        if (nums.empty()) break;
        const auto [b, n] = nums[pick(nums.size())];
        s.replace(b, n, kReplacements[pick(kReplacements.size())]);
        break;
      }
      case 5: {  // insert a structural character
        static const char kChars[] = "[]{}:,-#&*!|>'\"\t\n ?%@`";
        s.insert(pick(s.size() + 1), 1, kChars[pick(sizeof kChars - 1)]);
        break;
      }
      case 6: {  // deep nesting
        const std::size_t depth = 1 + pick(2000);
        const std::string nest = std::string(depth, '[') + "1" + std::string(depth, ']');
        const auto nums = numbers(s);
        if (nums.empty()) break;
        const auto [b, n] = nums[pick(nums.size())];
        s.replace(b, n, nest);
        break;
      }
      case 7: {  // a random byte
        s[pick(s.size())] = static_cast<char>(rng() & 0xff);
        break;
      }
      case 8: {  // truncate
        s.resize(pick(s.size() + 1));
        break;
      }
    }
  }
  return s;
}

TEST(LoaderMutation, EveryScene_EitherLoadsOrFailsWithAPositionedSceneError) {
  const std::filesystem::path dir = std::filesystem::path(RAYCAST_SOURCE_DIR) / "scenes";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());

  const int count = mutations_per_file();
  int loaded = 0, refused = 0;
  for (const auto& file : files) {
    const std::string original = read(file);
    const std::uint64_t seed = std::hash<std::string>{}(file.filename().string()) ^ 0x5eedULL;
    std::mt19937_64 rng(seed);
    for (int i = 0; i < count; ++i) {
      const std::string text = mutate(original, rng);
      SCOPED_TRACE(file.filename().string() + " mutation " + std::to_string(i) + " (seed " +
                   std::to_string(seed) + "):\n" + text);
      const auto start = std::chrono::steady_clock::now();
      try {
        // Relative mesh paths resolve against scenes/ like the real file.
        load_scene_text(text, file.filename().string(), dir.string());
        ++loaded;
      } catch (const SceneError& e) {
        ++refused;
        EXPECT_GE(e.line(), 0) << e.what();
        EXPECT_GE(e.column(), 0) << e.what();
        if (e.line() > 0) {
          // The line exists in the text (or is the line just past its end).
          const long lines = 1 + std::count(text.begin(), text.end(), '\n');
          EXPECT_LE(e.line(), lines + 1) << e.what();
          EXPECT_GT(e.column(), 0) << e.what();
        }
        EXPECT_FALSE(e.message().empty());
      } catch (const std::exception& e) {
        ADD_FAILURE() << "not a SceneError: " << typeid(e).name() << ": " << e.what();
      } catch (...) {
        ADD_FAILURE() << "non-standard exception";
      }
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      EXPECT_LT(seconds, 5.0) << "loading took " << seconds << " s";
      if (HasFailure()) return;
    }
  }
  std::printf("%d mutated scenes loaded, %d refused\n", loaded, refused);
}

}  // namespace
}  // namespace raycast
