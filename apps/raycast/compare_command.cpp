// `raycast compare A B [--block N] [--diff out.png] [--threshold T] [--json]`: how far apart two
// images are in 8-bit sRGB codes (docs/cli.md).
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "commands.h"
#include "io/image_diff.h"

namespace raycast::cli {
namespace {

struct CompareArgs {
  std::string a, b, diff;
  int block = 4;
  std::optional<double> threshold;
  bool json = false;
};

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

void print(const CompareArgs& args, const Image& a, const ImageDiff& d, bool close) {
  if (args.json) {
    std::printf(
        "{\"a\": %s, \"b\": %s, \"width\": %d, \"height\": %d, \"block\": %d, "
        "\"block_mean\": %.4f, \"mean\": %.4f, \"max\": %d, \"differing_pixels\": %lld, "
        "\"pixels\": %lld",
        json_string(args.a).c_str(), json_string(args.b).c_str(), a.width, a.height, d.block,
        d.block_mean, d.mean, d.max, d.differing, d.pixels);
    if (args.threshold)
      std::printf(", \"threshold\": %g, \"close\": %s", *args.threshold, close ? "true" : "false");
    std::printf("}\n");
    return;
  }
  std::printf(
      "block-%d mean abs diff %.3f, mean %.3f, max %d (8-bit sRGB codes); %lld of %lld "
      "pixels differ\n",
      d.block, d.block_mean, d.mean, d.max, d.differing, d.pixels);
  if (args.threshold)
    std::printf("%s (threshold %g)\n", close ? "close" : "not close", *args.threshold);
}

int run_compare(const CompareArgs& args) {
  Image a, b;
  try {
    a = load_image(args.a);
    b = load_image(args.b);
  } catch (const ImageError& e) {
    std::fprintf(stderr, "raycast compare: %s\n", e.what());
    return 2;
  }
  if (a.width != b.width || a.height != b.height) {
    std::fprintf(stderr, "raycast compare: the images' sizes differ: %s is %dx%d, %s is %dx%d\n",
                 args.a.c_str(), a.width, a.height, args.b.c_str(), b.width, b.height);
    return 2;
  }
  const ImageDiff d = compare_images(a, b, args.block);
  if (!args.diff.empty()) {
    try {
      save_image(difference_image(a, b), args.diff);
    } catch (const ImageError& e) {
      std::fprintf(stderr, "raycast compare: %s\n", e.what());
      return 1;
    }
  }
  const bool close = !args.threshold || d.block_mean <= *args.threshold;
  print(args, a, d, close);
  return close ? 0 : 1;
}

}  // namespace

Action add_compare_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "compare", "How far apart two images are: mean |difference| of 8-bit sRGB codes");
  auto args = std::make_shared<CompareArgs>();
  cmd->add_option("A", args->a, "First image (.png or .pfm)")->required();
  cmd->add_option("B", args->b, "Second image, the same size")->required();
  cmd->add_option("--block", args->block, "Average blocks of N x N pixels first (default 4)")
      ->check(CLI::Range(1, 1 << 16));
  cmd->add_option("--diff", args->diff, "Write |A - B| per channel as an image (.png, .pfm)");
  cmd->add_option("--threshold", args->threshold,
                  "Exit 1 when the block mean is above T, 0 when it is not")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--json", args->json, "Print the figures as JSON");
  return [args] { return run_compare(*args); };
}

}  // namespace raycast::cli
