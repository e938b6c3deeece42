#pragma once
// What the POV-Ray parser produces: the scene in POV-Ray's own (left-handed) coordinates and
// terms, before it is mapped to raycast's scene format by yaml_writer.
#include <array>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/height_image.h"
#include "math/vec3.h"
#include "pov/function_expr.h"
#include "pov/source.h"
#include "texture/texture_stack.h"

namespace raycast::pov {

/// rgb plus POV-Ray's filter and transmit.
struct Colour {
  double r = 0, g = 0, b = 0, filter = 0, transmit = 0;
};

/// One entry of a colour_map: the pattern value and its colour.
struct MapEntry {
  double at = 0;
  Colour colour;
};

/// A pigment: a colour, a checker, an image, or a pattern raycast does not build yet (then
/// `pattern` names it and `c0` is the colour it is drawn with: the map's middle colour).
struct Pigment {
  bool checker = false;
  Colour c0, c1{1, 1, 1, 0, 0};  // a plain pigment is c0; checker's defaults: blue and green
  double scale = 1;              // the checker's uniform scale (pigment transforms)
  std::string pattern;           // a pattern that is not built ("bozo", "agate", ...)
  std::string image_file;        // image_map { png "file" }: the file as resolved
  std::vector<MapEntry> map;     // the pattern's colour_map, kept for the texture system
  // The whole pigment in the texture system's terms (patterns, maps, warps, transforms), in
  // POV-Ray's coordinates and its colours as written (not linearised); null for a plain colour.
  std::shared_ptr<const texture::Pigment> model;
  bool checker_plain = true;  // a checker of two colours under uniform scales only
};

struct Finish {
  double ambient = 0.1, diffuse = 0.6;
  std::optional<double> ior;  // POV-Ray 3.1's `ior` in a finish (an interior's since)
  // POV-Ray 3.1's fade items in a finish (an interior's since; used when the interior has none)
  double fade_distance = 0, fade_power = 0;
  double phong = 0, phong_size = 40;
  double specular = 0, roughness = 0.05;
  double reflection = 0;  // `reflection F` or `reflection { F }`
  bool fresnel = false;   // `reflection { 0, 1 fresnel on }`
  bool conserve_energy = false;
  double brilliance = 1, metallic = 0, crand = 0;
  double reflection_min = 0, reflection_max = 0, reflection_falloff = 1;
  bool reflection_metallic = false;
};

/// interior { ior fade_distance fade_power fade_color }: what raycast builds of an interior.
/// Light travelling a distance d inside is attenuated when fade_distance and fade_power are both
/// set (POV-Ray's defaults, 0, turn it off); fade_color is the colour it fades towards.
struct Interior {
  std::optional<double> ior;
  double dispersion = 1;
  int dispersion_samples = 7;
  double fade_distance = 0, fade_power = 0;
  Colour fade_color;
};

struct Texture;
/// A patterned texture: the pattern's value picks (block patterns) or blends (texture_map) the
/// entries' textures, in POV-Ray's coordinates.
struct TextureMap {
  texture::Pattern pattern;
  bool average = false;  // `average`: the textures weighted by `at`, the pattern unused
  std::vector<double> at;
  std::vector<Texture> textures;
};

struct Texture {
  std::shared_ptr<const TextureMap> map;  // set: a patterned texture (pigment, normal unused)
  Pigment pigment;
  Finish finish;
  std::optional<Interior> interior;       // carried with the texture (raycast's material)
  std::string name;                       // the #declare name it came from, for the converted file
  std::optional<texture::Normal> normal;  // in POV-Ray's coordinates
  std::vector<Texture> under;  // layered textures: the layers beneath this one, bottom first
};

/// One transformation as written, in POV-Ray's coordinates.
struct XformOp {
  enum Kind { Translate, Rotate, Scale, Matrix };
  Kind kind = Translate;
  Vec3 v;
  std::array<double, 12> m{};  // matrix <...>: rows of POV-Ray's row-vector form
};

struct Light {
  enum Kind { Point, Spot, Cylinder } kind = Point;
  Vec3 position, point_at{0, 0, 1};
  Colour colour{1, 1, 1, 0, 0};
  double radius = 30, falloff = 45;  // spotlight degrees (cylinder: units, 0.75 and 1)
  double tightness = 0;
  double fade_distance = 0, fade_power = 0;  // 0: no fading
  bool parallel = false, shadowless = false;
  bool area = false;
  Vec3 axis1, axis2;
  int size1 = 1, size2 = 1;
  int adaptive = -1;  // -1: absent (every grid point sampled)
  bool jitter = false, circular = false, orient = false;
  Pos pos;
};

struct Node {
  enum Kind {
    Sphere,
    Box,
    Plane,
    Cylinder,
    Cone,
    Disc,
    Torus,
    Quadric,
    Poly,
    Isosurface,
    Lathe,
    Sor,
    Prism,  // points: the contour's <x, z> as (x, z, 0); values: the two heights
    Text,   // font, text; values: the thickness; points: the offset between letters
    Blob,   // values: the threshold; children: the components, Sphere or Cylinder nodes whose
            // values are the radius and the strength
    Superellipsoid,  // values: e, n
    HeightField,     // heights (image or function), image, image_type, smooth; values: water level
    Mesh,
    Triangle,  // triangle / smooth_triangle outside a mesh: points, and normals when smooth
    Union,
    Intersection,
    Difference,
    Merge,
    LightSource,  // a light_source (in a union, it moves with it)
    Reference     // object { Name } of a composite object: `ref`, placed by this node
  };
  Kind kind = Sphere;
  Pos pos;
  std::vector<Vec3> points;    // centre, corners, ends, normals, profile points (x, y, 0)
  std::vector<double> values;  // radii, distances, coefficients
  bool open = false;
  // poly/cubic/quartic/polynomial: coefficient of x^i y^j z^k, keyed by {i, j, k}
  std::map<std::array<int, 3>, double> terms;
  std::shared_ptr<const FnNode> function;     // isosurface: f(x, y, z) - threshold
  std::optional<std::array<Vec3, 2>> bounds;  // poly: bounded_by / intersection box; isosurface box
  bool contained_by_sphere = false;           // isosurface: bounds hold the sphere's box
  std::string spline;  // lathe, prism: linear_spline, quadratic_spline, cubic_spline, bezier_spline
  bool conic_sweep = false;  // prism: conic_sweep (else linear_sweep)
  std::string font, text;    // text: the font file as found on the library path, the string
  // height_field: the 16-bit heights (null: not built), the image file as found and its type
  // keyword (empty for a function, or when the extension names the type), `smooth`
  std::shared_ptr<const HeightImage> heights;
  std::string image, image_type;
  bool smooth = false;
  // mesh: triangles of vertex indices, and normals per vertex when smooth
  std::vector<Vec3> vertices, normals;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Node> children;
  std::optional<Light> light;       // LightSource
  std::shared_ptr<const Node> ref;  // Reference: shared, never copied
  std::size_t weight = 0;           // this object's count against Limits::scene_weight
  bool inverse = false;             // `inverse`: the solid's complement
  // clipped_by: the objects whose common inside keeps the surface, in the frame of this node's
  // parent (later transformations of the node are added to theirs as they are read)
  std::vector<Node> clipped_by;
  std::vector<Node> bounded_by;  // bounded_by's objects, kept for clipped_by { bounded_by }
  bool no_shadow = false;        // `no_shadow`: casts no shadow (its parts neither)
  bool no_image = false;         // `no_image`: camera rays pass through it
  bool no_reflection = false;    // `no_reflection`: mirrored rays pass through it
  std::string name;              // object { Name }: the declared name it was placed by
  std::vector<XformOp> xforms;
  std::optional<Texture> texture;
  std::size_t texture_at = 0;  // xforms[texture_at...] come after the texture: they move it
};

struct Camera {
  enum Kind {
    Perspective,
    Orthographic,
    Fisheye,
    UltraWideAngle,
    Omnimax,
    Panoramic,
    Cylinder,
    Spherical
  } kind = Perspective;
  int cylinder = 1;  // cylinder 1 to 4
  Vec3 location{0, 0, 0}, direction{0, 0, 1}, up{0, 1, 0}, right{1.33, 0, 0}, sky{0, 1, 0};
  double angle = 0;           // horizontal degrees; 0: not given
  double vertical_angle = 0;  // spherical's second angle; 0: not given
  Pos pos;
  bool given = false;
};

/// sky_sphere: its pigments bottom first in the texture system's terms (plain colours as solid
/// pigments, colours as written), its emission and the transformations of the whole sky.
struct SkySphere {
  std::vector<texture::Pigment> pigments;
  Colour emission{1, 1, 1, 0, 0};
  std::vector<XformOp> xforms;
};

/// fog: type 1 (constant) or 2 (ground), as written (colours not linearised).
struct Fog {
  int type = 1;
  Colour colour;
  double distance = 0;  // 0: POV-Ray leaves the fog out
  double offset = 0, alt = 0;
  Vec3 up{0, 1, 0};
  texture::Turbulence turbulence;
  double turb_depth = 0.5;
  std::vector<XformOp> xforms;
};

/// rainbow: as written (colours not linearised); arc angles in degrees, 360: the whole ring.
struct Rainbow {
  Vec3 direction{0, 0, 1};
  double angle = 0, width = 0;
  double distance = 1e7;
  std::vector<MapEntry> map;
  double jitter = 0;
  Vec3 up{0, 1, 0};
  double arc_angle = 360, falloff_angle = 360;
};

/// What the scene's global_settings, INI options and #version ask for.
struct Settings {
  double assumed_gamma = 1;  // 1 (linear), 2.2, or 0 for srgb
  bool gamma_given = false;  // assumed_gamma was written (POV-Ray 3.7 defaults apply if not)
  double version = 3.7;
  int width = 0, height = 0;  // from an INI file or +W/+H; 0: not given
  int antialias_depth = 0;    // +A: 0 off
  double antialias_threshold = 0.3;
};

struct PovScene {
  Camera camera;
  std::deque<Node> objects;  // a deque: 100,000s of nodes are never moved as it grows
  Colour background;
  std::optional<SkySphere> sky_sphere;
  std::vector<Fog> fogs;
  std::vector<Rainbow> rainbows;
  Colour ambient_light{1, 1, 1, 0, 0};
  int max_trace_level = 5;
  std::optional<double> adc_bailout;
  Settings settings;
  Sources sources;
  std::vector<std::string> warnings;  // formatted "file:line:col: warning: ..."
};

}  // namespace raycast::pov
