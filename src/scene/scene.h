// The scene as loaded from JSON (docs/scene-format.md): materials, world-space
// triangles, luminaires, sensors, cameras and precompute settings. Metres, right-handed,
// y up. Plain data; light/ turns luminaire distributions into evaluable photometry and
// mesh_preparation.h turns the triangles into per-vertex receivers.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "math/glazing.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/distribution_spec.h"
#include "scene/environment_spec.h"
#include "scene/triangle_soup.h"

namespace relight {

// A surface's material (docs/scene-format.md "Materials"). Lambertian with reflectance
// `albedo`, unless the scene gives `metallic` or `roughness`: then the glTF 2.0
// metallic–roughness BRDF (material/metallic_roughness.h) with `albedo` as its base colour.
struct Material {
  std::string name;
  Rgb albedo{0.5, 0.5, 0.5};  // diffuse reflectance (glTF base colour), linear, 0..1
  bool portal = false;        // window glass: an opening to the exterior
  bool glossy = false;        // `metallic` or `roughness` given
  double metallic = 0;        // 0..1 (glTF default when only roughness is given: 0)
  double roughness = 1;       // 0..1, α = roughness² (glTF default when only metallic is given)
  // Window glass's panes: a transmittance that falls with the angle of incidence
  // (math/glazing.h); none: the portal is an opening (its tint alone).
  std::optional<Glazing> glazing{};

  bool operator==(const Material&) const = default;
};

// A point luminaire with a type-C distribution. The photometric frame: γ = 0 along
// `aim`, the C0 half-plane contains `c0`, and C angles increase counter-clockwise
// seen from behind the luminaire (from above for a downlight): C90 = cross(c0, aim).
struct Luminaire {
  std::string name;
  Vec3 position;
  Vec3 aim{0, -1, 0};   // unit
  Vec3 c0{1, 0, 0};     // unit, orthogonal to aim
  Rgb color{1, 1, 1};   // chromaticity only: normalised so that luminance(color) == 1
  double dimmer = 1.0;  // 0..1 multiplier on the photometry
  // Physical luminous opening [width along C90, length along C0, height along the aim]
  // in metres, overriding the IES/LDT dimensions (or giving analytic distributions
  // one); all zero means a point source. Used for fractional direct visibility.
  Vec3 size{0, 0, 0};
  bool has_size = false;
  DistributionSpec distribution;
  std::string where;  // "FILE:JSON-PATH", for messages
};

// An observer of a task area for its glare check: the eye and the direction it looks.
struct TaskObserver {
  Vec3 position;
  Vec3 view{0, 0, -1};  // unit
};

// What EN 12464-1 asks of a task area (`relight probe --check`): the maintained average illuminance
// Ē >= em, the uniformity U0 = Emin/Ē >= u0, and UGR <= ugr_l at each observer; each requirement
// optional.
struct TaskRequirements {
  std::optional<double> em;     // lx
  std::optional<double> u0;     // 0..1
  std::optional<double> ugr_l;  // UGR limit
  std::vector<TaskObserver> observers;
};

struct SensorSet {
  std::string name;
  std::vector<Vec3> points;
  Vec3 normal{0, 1, 0};  // unit; every point of the set faces this way
  // Grid layout when the set came from a grid (index j*nu + i), 0 otherwise.
  int nu = 0, nv = 0;
  std::optional<TaskRequirements> task = std::nullopt;  // a task area (EN 12464-1)
};

// A window (Yue et al. 2009 §3): the triangles of its portal materials, through which light of the
// exterior environment enters.
struct Portal {
  std::string name;
  std::vector<std::uint32_t> materials;  // indices into Scene::materials, all "portal": true
  EnvironmentSpec environment;
  Rgb tint{1, 1, 1};                 // window glass colour (transmittance per channel)
  double frost_deg = 0;              // frosted glass: angular width of the blur of the shell
  std::optional<Glazing> glazing{};  // its materials' (all alike)
  // The shell-size check of Yue et al. 2009 §6: the nearest exterior object is
  // `exterior_distance` m away (0: only sky, no check) and the directional error l/(2r) may
  // be at most `shell_tolerance_deg`.
  double exterior_distance = 0;
  double shell_tolerance_deg = 5;
};

// Exterior geometry seen through the portals (Yue et al. 2009 §6, the dynamic environment): drawn
// into every portal's shell from the portal centre, over the sky, never part of the interior's
// transfer. The lighting state moves it (translate, turn about the vertical axis through `pivot`,
// hide).
struct ExteriorGeometry {
  std::string name;  // "" when unnamed (then it cannot be moved)
  TriangleSoup geometry;
  Vec3 pivot;  // centre of its bounding box
};

// A near-field area emitter (Sun 2005): a diffuse emitting surface of constant luminance that moves
// close to the receivers, lit by adaptive sampling of the incident radiance instead of by
// precomputed luminaire transfer. Not part of the room: it neither occludes nor reflects in the
// precompute. The lighting state moves (translate, turn about the vertical axis through `pivot`),
// dims and re-colours it.
struct Emitter {
  std::string name;
  TriangleSoup geometry;  // emitting on the front side of each triangle
  double luminance = 0;   // cd/m²
  Rgb color{1, 1, 1};     // chromaticity, luminance-normalised
  Vec3 pivot;             // centre of its bounding box
};

// A movable object of the room (Iwasaki et al. 2007): furniture that a lighting state moves
// (translate, turn about the vertical axis through `pivot`) or hides. At its scene placement it is
// part of the room — it occludes, reflects and receives like any surface — but it is not part of
// the precomputed transfer: the run time adds what it changes (sources/objects/object_lighting.h).
struct MovableObject {
  std::string name;
  TriangleSoup geometry;  // as the scene places it, each triangle with its material
  Vec3 pivot;             // centre of its bounding box
};

struct Camera {
  std::string name;
  Vec3 eye, target, up{0, 1, 0};
  double fov_deg = 60;  // vertical field of view
};

// The visibility cuts of a top-level environment (Iwasaki et al., Cyberworlds, §V.A: the capture
// paper, papers/003): `directions` leaves of the direction tree (a power of two ≤ 32,768), binary
// self-visibility cuts at every receiver merging nodes whose leaves agree to within `threshold` (a
// fraction below ½; 0: only nodes whose leaves all agree, exact), visibility cut fields of each
// movable object sampled on `sphere_count` concentric spheres of 6 · sphere_points² points between
// inner_radius and outer_radius times its bounding sphere's radius. Defaults: the paper's; it gives
// no threshold, 0 keeps every edge.
struct CutsSettings {
  int directions = 32768;
  int sphere_count = 32;
  int sphere_points = 32;
  double inner_radius = 1.2;
  double outer_radius = 10;
  double threshold = 0;
};

struct PrecomputeSettings {
  double max_edge = 0.25;  // m: mesh subdivision bound for per-vertex transfer
  int sh_order = 8;        // SH bands for indirect luminaire transfer (l < sh_order)
  double crease_deg = 30;  // smooth normals within this angle, split beyond
  int gather_rays = 256;   // rays per vertex for the gather operator
  // Rays per sensor: a sensor's reading is its own gather row, not smoothed by
  // interpolation between vertices, so it gets more rays (sensors are few).
  int sensor_gather_rays = 4096;
  double tolerance = 1e-4;  // relative change that ends the bounce iteration
  int max_bounces = 100;
  std::string direct = "exact";  // "exact" | "sh" (Dobashi et al. 1995's mode)
  // How the luminaires' and portals' interreflected SH transfer is stored: "fp16" (binary16 scaled
  // by a power of two, half the bytes for the run-time sum) | "fp32" (the sum is bound by the bytes
  // it streams; engine/transfer_blocks.h).
  std::string storage = "fp16";
  // Portals (Yue et al. 2009 §4.1): the direct component is a cubemap of portal_face_size² cells a
  // face per receiver, each cell the portal covers integrated over portal_samples_per_cell
  // directions (16× as many on the window's outline); the indirect component is SH, l <
  // portal_sh_order, RGB.
  int portal_face_size = 32;
  int portal_sh_order = 6;
  int portal_samples_per_cell = 4;
  // Near-field emitters (Sun 2005 §3.2.1): per-receiver SH transfer vectors with self-shadowing, l
  // < nearfield_sh_order, from nearfield_directions stratified directions (a square number), made
  // only when the scene has emitters; with nearfield_interreflection also their interreflected part
  // through the gather operator (RGB).
  int nearfield_sh_order = 4;
  int nearfield_directions = 256;
  bool nearfield_interreflection = false;
  // Occluders within this distance (m) shadow the near-field transfer; 0: a quarter of the
  // diagonal of the scene's bounding box.
  double nearfield_shadow_distance = 0;
  // Built when the scene has a top-level environment.
  CutsSettings cuts;
  // Whether the .rlt keeps the gather operator for the light the run time bounces itself (moved
  // and added luminaires, the exact sun, emitters, movable objects, material edits). false saves
  // its bytes in a scene that needs none of these (no portals, emitters, objects or top-level
  // environment); the state can then not move a luminaire or edit a material.
  bool runtime_bounce = true;
};

struct Bounds {
  Vec3 min{0, 0, 0}, max{0, 0, 0};
};

// Whether p lies in the box (its faces included).
inline bool contains(const Bounds& b, Vec3 p) {
  return p.x >= b.min.x && p.y >= b.min.y && p.z >= b.min.z && p.x <= b.max.x && p.y <= b.max.y &&
         p.z <= b.max.z;
}

struct Scene {
  std::filesystem::path file;  // the scene file (for messages and relative paths)
  std::vector<Material> materials;
  TriangleSoup geometry;  // world space; triangle_material indexes `materials`
  std::vector<Luminaire> luminaires;
  std::vector<SensorSet> sensors;
  std::vector<Camera> cameras;
  std::vector<Portal> portals;
  // A top-level environment: lights the scene from infinity wherever its geometry does not block it
  // (a showroom under a sky or a captured map): through the visibility cuts
  // (src/sources/environment/) at run time, exactly in `relight reference`.
  std::optional<EnvironmentSpec> environment;
  // The project's site: where the suns by "datetime" alone stand, its elevation and true north
  // (scene/environment_spec.h); none when the scene gives no "site".
  std::optional<Site> site;
  std::vector<ExteriorGeometry> exterior;
  std::vector<Emitter> emitters;
  std::vector<MovableObject> objects;
  PrecomputeSettings precompute;
  // CIE 97 maintenance factor of the electric lighting (0..1]; none when the scene does not
  // declare it (taken as 1 with a warning by the checks: EN 12464-1 asks for it).
  std::optional<double> maintenance_factor;
  // The static geometry's bounds when `geometry` is not loaded (a transfer file keeps the mesh
  // apart from its scene document): where a lighting state may hang a luminaire.
  std::optional<Bounds> mesh_bounds;

  // The geometry's bounds (mesh_bounds when the geometry is not loaded).
  Bounds bounds() const;
  std::size_t sensor_count() const;
  // Per material: the index of the portal that lists it, or −1 (opaque, or window glass that
  // no portal lists).
  std::vector<int> portal_of_material() const;
  const Camera* find_camera(const std::string& name) const;
};

}  // namespace relight
