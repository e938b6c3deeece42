#pragma once
// Run-time choice of the SIMD instruction set for the hot kernels (mesh traversal). One binary
// runs on any x86-64: the kernels are compiled once per ISA and picked at start from what the CPU
// offers, or from the RAYCAST_ISA environment variable (docs/architecture.md "ISA dispatch").
#include <optional>
#include <string_view>

namespace raycast {

/// The kernel paths, from portable to widest. kScalar is plain C++ (any architecture); the
/// others exist on x86-64 only.
enum class Isa { kScalar = 0, kSse4 = 1, kAvx2 = 2, kAvx512 = 3 };

inline constexpr Isa kAllIsas[] = {Isa::kScalar, Isa::kSse4, Isa::kAvx2, Isa::kAvx512};

/// "scalar", "sse4", "avx2", "avx512" (the spellings RAYCAST_ISA takes).
const char* isa_name(Isa isa);

/// The ISA of a RAYCAST_ISA spelling; nullopt for anything else.
std::optional<Isa> parse_isa(std::string_view name);

/// Whether this CPU (and OS) can run the kernels of `isa` and this build compiled them.
/// kSse4 needs SSE4.2 and POPCNT; kAvx2 needs AVX2, FMA, BMI1/2; kAvx512 needs AVX-512 F, VL,
/// DQ and BW.
bool isa_supported(Isa isa);

/// The widest supported ISA.
Isa best_isa();

/// The ISA the engine uses, decided once: RAYCAST_ISA when set and supported, else best_isa().
/// An unknown or unsupported RAYCAST_ISA does not stop the program: one warning goes to stderr
/// and the widest supported ISA not above the request (or best_isa() for an unknown name) is used.
Isa active_isa();

/// Why active_isa() is what it is: "cpu" (the CPU's best), "RAYCAST_ISA", or a warning text
/// when the request could not be honoured.
const char* active_isa_reason();

}  // namespace raycast
