#include "math/formula_noise.h"

namespace raycast {

namespace {
// Written by the loaders before the formulas that use it are compiled, always with the same
// value; the renders that read it start after that (their threads are made later).
FormulaNoise g_noise;
}  // namespace

void set_formula_noise(const FormulaNoise& noise) { g_noise = noise; }

const FormulaNoise& formula_noise() { return g_noise; }

}  // namespace raycast
