#include "render/relit_scene_image.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <optional>

#include "material/lambert.h"
#include "material/material_reflectance.h"
#include "render/glossy_pixels.h"
#include "runtime/direct_light.h"

namespace relight {

namespace {

// What the camera sees: the stored mesh, and the movable objects as the state places them
// (their triangles after the room's, their vertices after the room's vertices).
struct ShownScene {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<float> albedo;
  const RayTracer* tracer;  // RelitScene::shown_tracer: ids index `triangles`
};

ShownScene shown_with_objects(RelitScene& scene, const ObjectLighting& objects) {
  const TransferFile& t = scene.transfer();
  const std::span<const float> room_albedo = scene.relighter().vertex_albedo();
  const PlacedObjects& placed = objects.placed();
  ShownScene s{
      t.positions, t.triangles, {room_albedo.begin(), room_albedo.end()}, &scene.shown_tracer()};
  const auto base = static_cast<std::uint32_t>(t.positions.size());
  s.positions.insert(s.positions.end(), placed.positions.begin(), placed.positions.end());
  s.albedo.insert(s.albedo.end(), placed.albedo.begin(), placed.albedo.end());
  for (const Triangle& tri : placed.triangles) {
    s.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
  }
  return s;
}

// Room vertices' irradiance (the first 3·V of `room`), then the objects' vertices'.
std::vector<float> with_objects(std::span<const float> room, std::size_t vertices,
                                std::span<const float> objects) {
  std::vector<float> out(room.begin(), room.begin() + static_cast<std::ptrdiff_t>(3 * vertices));
  out.insert(out.end(), objects.begin(), objects.end());
  return out;
}

// BRDF samples of the room's reflection per glossy sub-pixel (the image takes 2 × 2 of them).
constexpr int kGlossySamples = 64;
// Primary rays per pixel along each axis (shade_vertices' default).
constexpr int kSamplesPerAxis = 2;

// The windows' light along a ray: the shell of the first portal it crosses, and with
// `with_suns` the suns' discs (traced exactly, so not in the shell).
Rgb window_luminance(const Relighter& lit, const RayTracer& windows, Vec3 origin, Vec3 dir,
                     bool with_suns) {
  const RayHit hit = windows.intersect({origin, dir});
  if (!hit.hit()) {
    // Past the scene: the top-level environment, if any (its sun disc included; without
    // `with_suns` its compact sources' discs show nothing, their light being counted exactly).
    const EnvironmentLighting* env = lit.environment();
    if (env == nullptr || env->environment() == nullptr) return {};
    const Vec3 w = normalize(dir);
    if (!with_suns) {
      for (const CompactSource& source : env->compact_sources()) {
        if (dot(w, source.disc.direction) >= source.disc.cos_angular_radius) return {};
      }
    }
    return env->environment()->radiance(w);
  }
  Rgb l = lit.shell(hit.triangle).radiance(dir);
  if (!with_suns) return l;
  for (const PortalSun& sun : lit.suns()) {
    if (sun.portal == hit.triangle && sun_disc_luminance(sun.disc, normalize(dir)) > 0) {
      l += sun.illuminance * (sun.disc.luminance / sun.disc.normal_illuminance);
    }
  }
  return l;
}

// The relit scene as vertex shading sees it: the room (and the objects as the state places
// them), the vertices' light and the windows.
struct VertexView {
  std::optional<ShownScene> shown;
  std::vector<float> irradiance;
};

VertexView make_vertex_view(RelitScene& scene) {
  const TransferFile& t = scene.transfer();
  const Relighter& lit = scene.relighter();
  const ObjectLighting* objects = lit.objects();
  VertexView view;
  if (objects != nullptr) {
    view.shown = shown_with_objects(scene, *objects);
    view.irradiance = with_objects(scene.irradiance(), t.vertex_count, objects->irradiance(true));
  } else {
    view.irradiance.assign(scene.irradiance().begin(), scene.irradiance().end());
  }
  return view;
}

VertexShadingInput vertex_input(RelitScene& scene, const VertexView& view,
                                std::function<Rgb(Vec3, Vec3)> background) {
  const TransferFile& t = scene.transfer();
  if (view.shown) {
    return {*view.shown->tracer,
            view.shown->positions,
            view.shown->triangles,
            view.shown->albedo,
            view.irradiance,
            {},
            std::move(background),
            {},
            {}};
  }
  return {scene.opaque_tracer(),
          t.positions,
          t.triangles,
          scene.relighter().vertex_albedo(),
          view.irradiance,
          {},
          std::move(background),
          {},
          {}};
}

// The relit scene's glossy surfaces as render/glossy_pixels.h shades them: the exact direct
// light's highlights (luminaires, suns; emitters as the diffuse surface of the same
// hemispherical albedo) and the room's reflection gathered from the relit vertices, for a
// pixel's hit point or a vertex. With `shown`, the objects as the state places them are seen,
// shadow, and shade by their own materials' BRDFs too.
class GlossyShading {
 public:
  GlossyShading(RelitScene& scene, const ShownScene* shown)
      : t_(scene.transfer()),
        lit_(scene.relighter()),
        view_environment_(scene.relighter().environment()),
        windows_(scene.portal_tracer()),
        objects_(shown != nullptr ? lit_.objects() : nullptr),
        direct_(scene),
        glossy_(glossy_materials(lit_.state().materials)),
        texture_(t_.view.scene.vertex_texture),
        pixels_{shown != nullptr ? *shown->tracer : scene.opaque_tracer(),
                shown != nullptr ? shown->positions : t_.positions,
                shown != nullptr ? shown->triangles : t_.triangles,
                {},
                [this](Vec3 origin, Vec3 dir) { return outside(origin, dir); },
                [this](const MetallicRoughness& m, Vec3 p, Vec3 n, Vec3 v) {
                  return direct(m, p, n, v);
                }} {
    if (glossy_.empty()) return;
    if (view_environment_ != nullptr) {
      view_environment_->prepare_view_cache(objects_ != nullptr ? objects_->placed().vertex_count()
                                                                : 0);
    }
    const ObjectLighting* objects = lit_.objects();
    const std::vector<float> total =
        objects != nullptr
            ? with_objects(scene.irradiance(), t_.vertex_count, objects->irradiance(true))
            : std::vector<float>(
                  scene.irradiance().begin(),
                  scene.irradiance().begin() + static_cast<std::ptrdiff_t>(3 * t_.vertex_count));
    const std::span<const float> albedo =
        shown != nullptr ? std::span<const float>(shown->albedo) : lit_.vertex_albedo();
    vertex_radiance_.resize(total.size());
    for (std::size_t i = 0; i < total.size(); ++i) {
      vertex_radiance_[i] = static_cast<float>(lambertian_radiance(albedo[i], total[i]));
    }
    // Direct light alone (`--max-bounces 1`): what the room reflects toward a glossy surface
    // is a second bounce.
    if (const EnvironmentLighting* env = lit_.environment(); env != nullptr && !env->bounces()) {
      std::fill(vertex_radiance_.begin(), vertex_radiance_.end(), 0.0f);
    }
    pixels_.vertex_radiance = vertex_radiance_;
  }
  GlossyShading(const GlossyShading&) = delete;
  GlossyShading& operator=(const GlossyShading&) = delete;

  bool empty() const { return glossy_.empty(); }

  // The direct irradiance at p (unit normal n) of every light (runtime/direct_light.h), as
  // `--direct pixel` takes it.
  Rgb direct_irradiance(Vec3 p, Vec3 n) const { return direct_.irradiance_at(p, n); }

  // The luminance toward v (unit) at a hit p (normal n) on `triangle` (the shown scene's: the
  // room's, then the objects') at barycentrics `bary`; none for a Lambertian triangle.
  std::optional<Rgb> at_hit(std::uint32_t triangle, const std::array<double, 3>& bary, Vec3 p,
                            Vec3 n, Vec3 v) const {
    if (glossy_.empty()) return std::nullopt;
    std::optional<MetallicRoughness> brdf;
    if (triangle < t_.triangles.size()) {
      if (triangle >= t_.triangle_material.size()) return std::nullopt;
      const std::int32_t g = glossy_.index.at(t_.triangle_material[triangle]);
      if (g < 0) return std::nullopt;
      // The base colour times the vertices' texture values (scene/surface_texture.h).
      brdf = glossy_.brdf[static_cast<std::size_t>(g)];
      if (!texture_.empty()) {
        Rgb at;
        for (std::size_t k = 0; k < 3; ++k) {
          at += vertex_texture_at(texture_, t_.triangles[triangle][k]) * bary[k];
        }
        brdf->albedo = brdf->albedo * at;
      }
    } else if (objects_ != nullptr &&
               triangle - t_.triangles.size() < objects_->placed().triangles.size()) {
      const Triangle& tri = objects_->placed().triangles[triangle - t_.triangles.size()];
      brdf = object_brdf(tri[0]);  // an object's triangle is of one material
      if (!brdf) return std::nullopt;
      Rgb at;
      for (std::size_t k = 0; k < 3; ++k) at += object_texture(tri[k]) * bary[k];
      brdf->albedo = brdf->albedo * at;
    } else {
      return std::nullopt;
    }
    // A stream per hit point: images are deterministic whatever the threads do.
    const std::uint64_t seed = std::hash<double>{}(p.x * 7.0 + p.y * 131.0 + p.z * 1031.0);
    Rgb l = glossy_pixel_radiance(pixels_, *brdf, p, n, v, kGlossySamples, seed);
    // The top-level environment through the cuts of the triangle's vertices.
    if (triangle < t_.triangles.size()) {
      for (std::size_t k = 0; k < 3; ++k) {
        l += environment_reflection(t_.triangles[triangle][k], *brdf, v) * bary[k];
      }
    } else if (const EnvironmentLighting* env = lit_.environment(); env != nullptr) {
      const Triangle& tri = objects_->placed().triangles[triangle - t_.triangles.size()];
      const MetallicRoughnessToward toward(*brdf, n, v);
      for (std::size_t k = 0; k < 3; ++k) {
        l += env->reflected_object(tri[k], objects_->placed(), toward) * bary[k];
      }
    }
    return l;
  }

  // Per vertex of the shown scene (3 each): the luminance of a glossy vertex (the room's, then
  // the shown objects') toward `eye`, with `samples` BRDF samples of the room's reflection;
  // NaN elsewhere, and at the vertices `needed` (when given, 1 per vertex) leaves out.
  std::vector<float> vertex_luminance(Vec3 eye, int samples,
                                      std::span<const std::uint8_t> needed = {}) const {
    std::vector<float> out(pixels_.positions.size() * 3, std::numeric_limits<float>::quiet_NaN());
    if (glossy_.empty()) return out;
    const std::vector<std::uint32_t>& material = t_.view.scene.vertex_material;
    const std::size_t room = material.size() < t_.vertex_count ? 0 : t_.vertex_count;
    const std::size_t objects = objects_ != nullptr ? objects_->placed().vertex_count() : 0;
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, t_.vertex_count + objects, 64), [&](const auto& r) {
          for (std::size_t v = r.begin(); v != r.end(); ++v) {
            if (!needed.empty() && needed[v] == 0) continue;
            std::optional<MetallicRoughness> brdf;
            Vec3 p, n;
            if (v < t_.vertex_count) {
              if (v >= room || material[v] == kNoMaterial) continue;
              const std::int32_t g = glossy_.index.at(material[v]);
              if (g < 0) continue;
              brdf = glossy_.brdf[static_cast<std::size_t>(g)];
              brdf->albedo = brdf->albedo * vertex_texture_at(texture_, v);
              p = t_.positions[v];
              n = t_.view.scene.receiver_normals[v];
            } else {
              const std::size_t q = v - t_.vertex_count;
              const PlacedObjects& placed = objects_->placed();
              if (!placed.visible(placed.object_of_vertex(q))) continue;
              brdf = object_brdf(q);
              if (!brdf) continue;
              brdf->albedo = brdf->albedo * object_texture(q);
              p = placed.positions[q];
              n = placed.normals[q];
            }
            const Vec3 to_eye = eye - p;
            const double d = length(to_eye);
            if (!(d > 0) || dot(to_eye, n) <= 0) continue;  // seen from behind: as diffuse
            Rgb l = glossy_pixel_radiance(pixels_, *brdf, p, n, to_eye / d, samples, v);
            const MetallicRoughnessToward weight(*brdf, n, to_eye / d);
            // The environment through the cuts (its compact sources are in direct()): the
            // specular lobe at each node, eight nodes at a time, the diffuse layer from its
            // sums kept while the light stays (each vertex is one thread's, as diffuse_layer
            // asks).
            if (EnvironmentLighting* env = view_environment_; env != nullptr) {
              const EnvironmentLighting::DiffuseLayerSums& sums =
                  v < t_.vertex_count
                      ? env->diffuse_layer(v, n, brdf->roughness)
                      : env->object_diffuse_layer(v - t_.vertex_count, objects_->placed(), n,
                                                  brdf->roughness);
              l += v < t_.vertex_count
                       ? env->reflected_specular(v, weight)
                       : env->reflected_object_specular(v - t_.vertex_count, objects_->placed(),
                                                        *brdf, to_eye / d);
              l += weight.diffuse_of_sums(sums.e, sums.a, sums.b);
            }
            out[3 * v] = static_cast<float>(l.r);
            out[3 * v + 1] = static_cast<float>(l.g);
            out[3 * v + 2] = static_cast<float>(l.b);
          }
        });
    return out;
  }

 private:
  // The top-level environment's light that room vertex v reflects toward v_out (unit) by
  // `brdf`, through its self-visibility cut (sources/environment/environment_lighting.h); 0 without
  // an environment; its compact sources are traced per pixel in direct(). The BRDF samples of
  // glossy_pixel_radiance see no environment past the scene (outside()), so it is counted once.
  Rgb environment_reflection(std::size_t v, const MetallicRoughness& brdf, Vec3 v_out) const {
    const EnvironmentLighting* env = lit_.environment();
    if (env == nullptr) return {};
    const Vec3 n = t_.view.scene.receiver_normals[v];
    return env->reflected(v, MetallicRoughnessToward(brdf, n, v_out));
  }

  // The BRDF of object vertex q (PlacedObjects order) when its material is glossy; none for
  // a Lambertian one or a file from before the objects kept their materials.
  std::optional<MetallicRoughness> object_brdf(std::size_t q) const {
    const PlacedObjects& placed = objects_->placed();
    const std::size_t k = placed.object_of_vertex(q);
    const std::vector<std::uint32_t>& material = objects_->meshes()[k].vertex_material;
    const std::size_t v = q - placed.first_vertex[k];
    if (v >= material.size()) return std::nullopt;
    const std::int32_t g = glossy_.index.at(material[v]);
    if (g < 0) return std::nullopt;
    return glossy_.brdf[static_cast<std::size_t>(g)];
  }
  // Object vertex q's base colour texture value (1 without a texture).
  Rgb object_texture(std::size_t q) const {
    const PlacedObjects& placed = objects_->placed();
    const std::size_t k = placed.object_of_vertex(q);
    return vertex_texture_at(std::span<const float>(objects_->meshes()[k].texture),
                             q - placed.first_vertex[k]);
  }

  // The shell through a window; the sun disc is exact in direct().
  Rgb outside(Vec3 origin, Vec3 dir) const {
    const RayHit hit = windows_.intersect({origin, dir});
    return hit.hit() ? lit_.shell(hit.triangle).radiance(dir) : Rgb{};
  }

  // Every light's direct light reflected toward v: the BRDF toward each light's direction; an
  // emitter (an area light) as the diffuse surface of the same hemispherical albedo.
  Rgb direct(const MetallicRoughness& m, Vec3 p, Vec3 n, Vec3 v) const {
    Rgb l;
    direct_.for_each_at(p, n, false, [&](LightKind, std::string_view, const SeenLight& light) {
      if (max_component(light.irradiance) <= 0) return;
      l += light.area ? lambertian_radiance(hemispherical_albedo(m), light.irradiance)
                      : metallic_roughness_brdf(m, n, light.direction, v) * light.irradiance;
    });
    return l;
  }

  const TransferFile& t_;
  const Relighter& lit_;
  // The same relighter's environment (null: none), whose kept diffuse-layer sums the view
  // updates (vertex_luminance).
  EnvironmentLighting* view_environment_;
  const RayTracer& windows_;
  const ObjectLighting* objects_;  // the objects shown (null: none)
  const DirectLight direct_;
  const GlossyMaterials glossy_;
  const std::span<const float> texture_;
  std::vector<float> vertex_radiance_;
  GlossyPixelScene pixels_;
};

}  // namespace

std::vector<Rgb> relit_scene_luminance(RelitScene& scene, std::span<const Ray> rays,
                                       bool with_suns) {
  const VertexView view = make_vertex_view(scene);
  const RayTracer& windows = scene.portal_tracer();
  const Relighter& lit = scene.relighter();
  VertexShadingInput input = vertex_input(scene, view, [&](Vec3 origin, Vec3 dir) {
    return window_luminance(lit, windows, origin, dir, with_suns);
  });
  // Glossy vertices as seen from the rays' eye (the first ray's origin: one observer), only
  // those of the triangles the rays meet.
  std::vector<RayHit> hits(rays.size());
  input.tracer.intersect(rays, hits);
  const GlossyShading glossy(scene, view.shown ? &*view.shown : nullptr);
  const std::vector<float> toward_eye =
      glossy.empty() || rays.empty()
          ? std::vector<float>{}
          : glossy.vertex_luminance(rays.front().origin, kGlossySamples,
                                    vertices_hit(hits, input.triangles, input.positions.size()));
  input.vertex_luminance = toward_eye;
  std::vector<Rgb> out(rays.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 256), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      out[i] = shade_hit(input, rays[i].origin, rays[i].direction, hits[i]).luminance;
    }
  });
  return out;
}

ShadedImages render_relit_scene(RelitScene& scene, const Camera& camera, int width, int height,
                                bool pixel_direct) {
  const TransferFile& t = scene.transfer();
  const RayTracer& room = scene.opaque_tracer();
  const RayTracer& windows = scene.portal_tracer();
  const PinholeCamera pinhole = make_pinhole_camera(camera, width, height);
  const Relighter& lit = scene.relighter();
  const auto background = [&](Vec3 origin, Vec3 dir) {
    return window_luminance(lit, windows, origin, dir, true);
  };
  if (!pixel_direct) {
    // Glossy vertices send their own luminance toward the eye: only those of the triangles the
    // image's rays meet are shaded (the capture paper's §V.B), and the rays are traced once.
    const VertexView view = make_vertex_view(scene);
    VertexShadingInput input = vertex_input(scene, view, background);
    const GlossyShading glossy(scene, view.shown ? &*view.shown : nullptr);
    if (glossy.empty()) return shade_vertices(pinhole, input, kSamplesPerAxis);
    const std::vector<RayHit> hits = trace_primary(pinhole, input.tracer, kSamplesPerAxis);
    const std::vector<float> toward_eye = glossy.vertex_luminance(
        pinhole.eye, kGlossySamples, vertices_hit(hits, input.triangles, input.positions.size()));
    input.vertex_luminance = toward_eye;
    return shade_vertices(pinhole, input, kSamplesPerAxis, hits);
  }
  const ObjectLighting* objects = lit.objects();
  const std::optional<ShownScene> shown =
      objects != nullptr ? std::optional(shown_with_objects(scene, *objects)) : std::nullopt;
  const RayTracer& visible = shown ? *shown->tracer : room;
  const std::vector<Vec3>& positions = shown ? shown->positions : t.positions;
  const std::vector<Triangle>& triangles = shown ? shown->triangles : t.triangles;
  const std::span<const float> albedo =
      shown ? std::span<const float>(shown->albedo) : lit.vertex_albedo();
  std::vector<float> indirect = scene.indirect_irradiance();
  if (objects != nullptr) {
    indirect = with_objects(indirect, t.vertex_count, objects->irradiance(false));
  }
  // Glossy triangles, the room's and the objects' (the state's materials), shade by their BRDF
  // (render/glossy_pixels.h): the exact direct light's highlights and the room's reflection
  // gathered from the relit vertices.
  const GlossyShading glossy(scene, shown ? &*shown : nullptr);
  const auto glossy_radiance = [&](std::uint32_t triangle, const std::array<double, 3>& bary,
                                   Vec3 p, Vec3 n, Vec3 v) -> std::optional<Rgb> {
    return glossy.at_hit(triangle, bary, p, n, v);
  };
  return shade_vertices(pinhole, {visible,
                                  positions,
                                  triangles,
                                  albedo,
                                  indirect,
                                  [&](Vec3 p, Vec3 n) { return glossy.direct_irradiance(p, n); },
                                  background,
                                  glossy_radiance,
                                  {}});
}

std::vector<float> glossy_vertex_luminance(RelitScene& scene, Vec3 eye, int samples,
                                           std::span<const std::uint8_t> needed) {
  const VertexView view = make_vertex_view(scene);
  const GlossyShading glossy(scene, view.shown ? &*view.shown : nullptr);
  return glossy.vertex_luminance(eye, samples, needed);
}

std::vector<std::uint8_t> vertices_in_view(RelitScene& scene, const Camera& camera, int width,
                                           int height) {
  const VertexView view = make_vertex_view(scene);
  const VertexShadingInput input = vertex_input(scene, view, {});
  return vertices_hit(
      trace_primary(make_pinhole_camera(camera, width, height), input.tracer, kSamplesPerAxis),
      input.triangles, input.positions.size());
}

}  // namespace relight
