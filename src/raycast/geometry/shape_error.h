#pragma once
// The error the make_* functions throw for a parameter outside its domain.
#include <cstdio>
#include <stdexcept>
#include <string>

namespace raycast {

/// A shape parameter outside its domain. `parameter()` is its name as the scene format spells it
/// ("phi_max", "vertices"), `requirement()` what was expected and what came ("must be in
/// (0, 360], got 400"); what() is both. Scene readers point their positioned error at the
/// parameter; the C++ and Python APIs pass what() on.
class ShapeParameterError : public std::invalid_argument {
 public:
  ShapeParameterError(const std::string& parameter, const std::string& requirement)
      : std::invalid_argument(parameter + " " + requirement),
        parameter_(parameter),
        requirement_(requirement) {}
  const std::string& parameter() const { return parameter_; }
  const std::string& requirement() const { return requirement_; }

 private:
  std::string parameter_, requirement_;
};

/// A number as messages print it ("%g").
inline std::string format_parameter(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace raycast
