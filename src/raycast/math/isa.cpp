#include "math/isa.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace raycast {

const char* isa_name(Isa isa) {
  switch (isa) {
    case Isa::kScalar:
      return "scalar";
    case Isa::kSse4:
      return "sse4";
    case Isa::kAvx2:
      return "avx2";
    case Isa::kAvx512:
      return "avx512";
  }
  return "?";
}

std::optional<Isa> parse_isa(std::string_view name) {
  for (Isa isa : kAllIsas)
    if (name == isa_name(isa)) return isa;
  return std::nullopt;
}

bool isa_supported(Isa isa) {
#if defined(__x86_64__) && defined(__GNUC__)
  // __builtin_cpu_supports also checks that the OS saves the wide registers (XGETBV).
  switch (isa) {
    case Isa::kScalar:
      return true;
    case Isa::kSse4:
      return __builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt");
    case Isa::kAvx2:
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
             __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
    case Isa::kAvx512:
      return isa_supported(Isa::kAvx2) && __builtin_cpu_supports("avx512f") &&
             __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") &&
             __builtin_cpu_supports("avx512bw");
  }
  return false;
#else
  return isa == Isa::kScalar;
#endif
}

Isa best_isa() {
  Isa best = Isa::kScalar;
  for (Isa isa : kAllIsas)
    if (isa_supported(isa)) best = isa;
  return best;
}

namespace {

struct Choice {
  Isa isa = Isa::kScalar;
  std::string reason;
};

Choice decide() {
  const char* env = std::getenv("RAYCAST_ISA");
  if (!env || !*env) return {best_isa(), "cpu"};
  const std::optional<Isa> want = parse_isa(env);
  Choice c;
  if (!want) {
    c = {best_isa(), std::string("RAYCAST_ISA=") + env +
                         " is not one of scalar, sse4, avx2, avx512; using " +
                         isa_name(best_isa())};
  } else if (!isa_supported(*want)) {
    Isa fallback = Isa::kScalar;
    for (Isa isa : kAllIsas)
      if (isa <= *want && isa_supported(isa)) fallback = isa;
    c = {fallback, std::string("RAYCAST_ISA=") + env + " is not supported by this CPU; using " +
                       isa_name(fallback)};
  } else {
    return {*want, "RAYCAST_ISA"};
  }
  std::fprintf(stderr, "raycast: warning: %s\n", c.reason.c_str());
  return c;
}

const Choice& choice() {
  static const Choice c = decide();
  return c;
}

}  // namespace

Isa active_isa() { return choice().isa; }

const char* active_isa_reason() { return choice().reason.c_str(); }

}  // namespace raycast
