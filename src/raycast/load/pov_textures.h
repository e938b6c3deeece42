#pragma once
// POV-Ray textures (the interpreter's description) as the texture system's stacks: colours made
// linear by the scene's gamma, layers bottom first, finishes in POV-Ray's terms.
#include <functional>
#include <map>
#include <memory>

#include "pov/pov_scene.h"
#include "texture/texture_stack.h"

namespace raycast {

/// Whether a POV-Ray texture needs the texture system: a patterned texture, a pattern (other than a
/// checker of two colours under uniform scales, which the plain checker draws), a normal, layers,
/// or a finish term plain materials lack (brilliance, metallic, crand, variable or metallic
/// reflection).
bool needs_texture_system(const pov::Texture& t);

class PovTextureBuilder {
 public:
  /// `linear` maps a colour channel as written to linear light.
  explicit PovTextureBuilder(std::function<double(double)> linear) : linear_(std::move(linear)) {}

  /// The stack for a texture and its layers; pigments shared between textures are converted
  /// once.
  std::shared_ptr<const texture::TextureStack> stack(const pov::Texture& t, int depth = 0);
  /// A pigment with its colours (and its maps' pigments' colours) made linear.
  std::shared_ptr<const texture::Pigment> pigment(const texture::Pigment& p, int depth = 0);

 private:
  texture::TextureLayer layer(const pov::Texture& t);
  texture::Rgbft colour(const texture::Rgbft& c) const;

  std::function<double(double)> linear_;
  std::map<const texture::Pigment*, std::shared_ptr<const texture::Pigment>> pigments_;
};

}  // namespace raycast
