#pragma once
// What a user asks of the POV-Ray reader besides the scene file: the library path, declared
// values (`Declare=` / `-D`-style), the clock, the image size, strictness, and the bounds that
// keep a scene program from running away.
#include <cstddef>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "pov/object_queries.h"

namespace raycast::pov {

/// Bounds on what a scene program may do; each error names the bound and how to raise it.
struct Limits {
  long long loop_iterations = 10'000'000;   // #while and #for iterations in all
  int macro_depth = 400;                    // macro calls nested (recursion)
  int include_depth = 64;                   // #include files nested
  std::size_t array_elements = 50'000'000;  // elements of one array
  std::size_t string_bytes = 16u << 20;     // length of one string
  std::size_t scene_weight = 200'000'000;   // objects, vertices, triangles, terms in all
  long long file_reads = 10'000'000;        // #read values in all
};

struct Options {
  std::vector<std::string> library_paths;  // searched after the scene's folder, in order
  std::vector<std::pair<std::string, std::string>> declares;  // NAME, value text
  bool strict = false;  // warnings about what raycast does not render become errors
  double clock = 0;
  bool clock_on = false;
  double initial_clock = 0, final_clock = 1;
  int frame = 0, initial_frame = 1, final_frame = 1;
  int width = 0, height = 0;  // the image's size for image_width/image_height (0: 640 x 480)
  bool antialias = false;     // +A / Antialias=on: POV-Ray's adaptive method 1
  double antialias_threshold = 0.3;
  int antialias_depth = 3;
  std::ostream* debug = nullptr;    // where #debug and #warning write (nullptr: standard error)
  bool system_library_path = true;  // read Library_Path from the user's and the system's povray.ini
  bool file_output = true;  // #fopen ... write/append allowed (the fuzz target turns it off)
  Limits limits;
  std::shared_ptr<ObjectQueries> object_queries;  // trace, inside, min/max_extent (nullptr: 0)
};

/// The library folders POV-Ray's own configuration names: Library_Path entries of
/// ~/.povray/3.7/povray.ini and /etc/povray/3.7/povray.ini (in that order), then the
/// RAYCAST_POV_LIBRARY_PATH environment variable's folders (':'-separated) before them.
std::vector<std::string> configured_library_paths();

}  // namespace raycast::pov
