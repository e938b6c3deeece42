#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench/bench.h"
#include "commands.h"
#include "io/scene_error.h"

namespace raycast::cli {

namespace {

// CLI::Range lets NaN through (every comparison with it is false): the tuning numbers are
// checked to be finite first.
const CLI::Validator kFinite(
    [](std::string& s) {
      return std::isfinite(std::strtod(s.c_str(), nullptr))
                 ? std::string()
                 : "Value " + s + " is not a finite number";
    },
    "FINITE");

}  // namespace

Action add_bench_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "bench", "Trace a deterministic ray set through a mesh or scene; compare with Embree");
  struct Options {
    std::string scene, mesh, procedural, rays = "primary", vs;
    int threads = 0, repeat = 3;
    bool json = false;
    bool packets = false;
    int packet_width = 0;  // 0: not given (8); --packet-width alone implies --packets
  };
  auto opt = std::make_shared<Options>();
  auto* scene = cmd->add_option("SCENE", opt->scene, "Scene file (meshes only with --vs embree)");
  auto* mesh = cmd->add_option("--mesh", opt->mesh, "Mesh file (.obj, .ply, .stl, .gltf, .glb)");
  auto* proc =
      cmd->add_option("--procedural", opt->procedural, "NAME:TRIANGLES, NAME sphere or forest");
  scene->excludes(mesh)->excludes(proc);
  mesh->excludes(proc);
  cmd->add_option("--rays", opt->rays, "primary (1024x1024 camera), incoherent or shadow")
      ->check(CLI::IsMember({"primary", "incoherent", "shadow"}));
  cmd->add_option("--vs", opt->vs, "Trace the same rays with a peer: embree")
      ->check(CLI::IsMember({"embree"}));
  cmd->add_option("--threads", opt->threads, "Threads (default: all cores)")
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--repeat", opt->repeat, "Tracing passes; the fastest counts (default 3)")
      ->check(CLI::Range(1, 100));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  // A flag and a separate width (not an option with an optional value, which would swallow a
  // SCENE given after it).
  cmd->add_flag("--packets", opt->packets,
                "Primary rays in packets (one mesh); with --vs embree, rtcIntersect8/16");
  cmd->add_option("--packet-width", opt->packet_width, "Rays per packet: 8 (default) or 16")
      ->check(CLI::IsMember({8, 16}));
  auto bvh = std::make_shared<MeshBvhConfig>();
  cmd->add_option("--leaf-size", bvh->max_leaf_size, "Tuning: most triangles per leaf (1-16)")
      ->check(CLI::Range(1, 16));
  cmd->add_option("--bins", bvh->bins, "Tuning: SAH bins per axis (2-64)")
      ->check(CLI::Range(2, 64));
  cmd->add_option("--traversal-cost", bvh->traversal_cost,
                  "Tuning: SAH node cost per group of 4 triangles")
      ->check(kFinite)
      ->check(CLI::Range(0.01, 100.0));
  cmd->add_option("--split-budget", bvh->split_budget,
                  "Tuning: extra split references per triangle (early split clipping; 0: off)")
      ->check(kFinite)
      ->check(CLI::Range(0.0, 4.0));
  cmd->add_option("--split-min-ratio", bvh->split_min_ratio,
                  "Tuning: split only pieces whose box exceeds this many times their area (8)")
      ->check(kFinite)
      ->check(CLI::Range(0.0, 1e6));
  return [opt, bvh] {
    BenchOptions o;
    o.scene = opt->scene;
    o.mesh_file = opt->mesh;
    o.procedural = opt->procedural;
    if (o.scene.empty() && o.mesh_file.empty() && o.procedural.empty())
      throw SceneError("bench", 0, 0, "give a SCENE, --mesh FILE or --procedural NAME:TRIANGLES");
    o.rays = parse_bench_rays(opt->rays);
    o.vs_embree = opt->vs == "embree";
    o.packets = opt->packets || opt->packet_width != 0;
    o.packet_width = opt->packet_width != 0 ? opt->packet_width : 8;
    o.threads = opt->threads;
    o.repeat = opt->repeat;
    o.bvh = *bvh;
    const BenchResult r = run_bench(o);
    std::fputs(format_bench(r, opt->json).c_str(), stdout);
    return 0;
  };
}

}  // namespace raycast::cli
