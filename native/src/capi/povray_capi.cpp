// SPDX-License-Identifier: GPL-3.0-or-later
// The POV-Ray exporter behind the C ABI (fracterra/povray.h).
#include <cmath>
#include <memory>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "io/atomic_file.hpp"
#include "povray/heightfield_export.hpp"
#include "povray/pov_params.hpp"
#include "povray/render.hpp"
#include "povray/scene.hpp"
#include "povray/sdl_writer.hpp"
#include "povray/sphere_sweep_export.hpp"

using ft::capi::guarded;

namespace {

std::string path_arg(const char* name, const char* path) {
  ft::check_not_null(name, path);
  if (!*path) ft::invalid(std::string(name) + " must not be empty");
  return path;
}

ft::Vec3 vec3(const double* v) { return {v[0], v[1], v[2]}; }

ft::pov::SceneMaterial material_of(const ft_pov_material& m) {
  ft::pov::SceneMaterial s;
  s.color = vec3(m.color);
  s.emission = vec3(m.emission);
  s.roughness = m.roughness;
  s.specular = m.specular;
  s.water = m.water != 0;
  return s;
}

ft::pov::SceneLight light_of(const ft_pov_light& l) {
  ft::pov::SceneLight s;
  s.kind = ft::pov::LightKind(l.kind);
  s.color = vec3(l.color);
  s.power = l.power;
  s.location = vec3(l.location);
  s.direction = vec3(l.direction);
  s.spot_size_deg = l.spot_size_deg;
  s.spot_blend = l.spot_blend;
  s.spot_cos_power = l.spot_cos_power;
  s.area_u = vec3(l.area_u);
  s.area_v = vec3(l.area_v);
  s.area_ellipse = l.area_ellipse != 0;
  s.shadows = l.shadows != 0;
  return s;
}

// The data fields of another program's scene (ABI 2.26); the table checks only settings.
void apply_scene_data(const ft_pov_scene_params& p, ft::pov::SceneParams& s) {
  ft::check_int_range("light_count", p.light_count, 0, 1024);
  if (p.light_count > 0) ft::check_not_null("lights", p.lights);
  for (int32_t i = 0; i < p.light_count; ++i) s.lights.push_back(light_of(p.lights[i]));
  if (p.line_materials)
    for (int32_t i = 0; i < p.line_set_count; ++i) s.lines[size_t(i)].material = material_of(p.line_materials[i]);
  if (p.rivers) s.rivers = &p.rivers->set;
  if (p.water_material) s.water_material = material_of(*p.water_material);
  ft::check_int_range("mesh_count", p.mesh_count, 0, 65536);
  if (p.mesh_count > 0) ft::check_not_null("meshes", p.meshes);
  for (int32_t i = 0; i < p.mesh_count; ++i) {
    ft::check_not_null("meshes[i].mesh", p.meshes[i].mesh);
    s.meshes.push_back({&p.meshes[i].mesh->mesh, material_of(p.meshes[i].material), p.meshes[i].smooth != 0});
  }
}

}  // namespace

extern "C" {

FT_API ft_status ft_pov_scene_params_init(ft_pov_scene_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::defaults_of<ft_pov_scene_params>(ft::pov::scene_param_table());
  });
}

FT_API ft_status ft_pov_write_scene(const ft_pov_scene_params* given, const char* pov_path) {
  return guarded([&] {
    ft::check_not_null("params", given);
    const ft_pov_scene_params params = ft::upgraded(ft::pov::scene_param_table(), *given);
    const ft_pov_scene_params* p = &params;
    const std::string path = path_arg("pov_path", pov_path);
    // The data fields (the table checks only settings).
    ft::check_int_range("line_set_count", p->line_set_count, 0, 1024);
    if (p->line_set_count > 0) ft::check_not_null("lines", p->lines);
    ft::pov::SceneParams s;
    ft::pov::apply_scene_settings(*p, s);
    if (p->terrain) s.terrain = &p->terrain->hf;
    s.terrain_colors = p->terrain_colors;
    for (int32_t i = 0; i < p->line_set_count; ++i) {
      ft::check_not_null("lines[i].lines", p->lines[i].lines);
      s.lines.push_back({&p->lines[i].lines->set, ft::pov::LineKind(p->lines[i].kind), p->lines[i].radius});
    }
    apply_scene_data(*p, s);
    if (p->image_path) s.image_path = path_arg("image_path", p->image_path);
    ft::pov::write_scene(s, path);
  });
}

FT_API ft_status ft_pov_write_heightfield(const ft_heightfield* hf, const char* png_path, const char* inc_path,
                                         const char* name, double world_size_x, double world_size_y,
                                         double vertical_scale, double* z_min, double* z_max) {
  return guarded([&] {
    ft::check_not_null("heightfield", hf);
    const std::string png = path_arg("png_path", png_path);
    std::unique_ptr<ft::io::AtomicFile> inc;
    std::string id;
    if (inc_path) {
      id = ft::pov::identifier(name ? name : "", "name");
      inc = std::make_unique<ft::io::AtomicFile>(path_arg("inc_path", inc_path));  // checks the folder first
    }
    ft::pov::validate_terrain(hf->hf, world_size_x, world_size_y, vertical_scale);
    const auto place = ft::pov::write_heightfield_png(hf->hf, png, world_size_x, world_size_y, vertical_scale);
    if (inc) {
      const std::string ref = ft::pov::relative_path(png, ft::pov::folder_of(inc_path));
      inc->write("// fracterra height_field (16-bit PNG, heights in real units)\n#declare " + id + " = " +
                 ft::pov::heightfield_sdl(ref, place, NAN));
      inc->commit();
    }
    if (z_min) *z_min = place.z_min;
    if (z_max) *z_max = place.z_max;
  });
}

FT_API ft_status ft_pov_sweep_params_init(ft_pov_sweep_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::defaults_of<ft_pov_sweep_params>(ft::pov::sweep_param_table());
  });
}

FT_API ft_status ft_pov_write_sweeps(const ft_polylines* lines, const ft_pov_sweep_params* p,
                                     const char* inc_path, const char* name) {
  return guarded([&] {
    ft::check_not_null("lines", lines);
    ft::check_not_null("params", p);
    const ft::pov::SweepOptions o = ft::pov::sweep_options(ft::upgraded(ft::pov::sweep_param_table(), *p));
    const std::string path = path_arg("inc_path", inc_path);
    const std::string id = ft::pov::identifier(name ? name : "", "name");
    const std::string sdl = ft::pov::sweeps_sdl(lines->set, o);
    if (sdl.empty()) ft::invalid("the polyline set has no vertices");
    ft::io::write_file_atomically(path, "// fracterra polylines as chunked sphere_sweeps\n#declare " + id + " = " + sdl);
  });
}

FT_API ft_status ft_pov_render(const char* pov_path, const char* out_png, int32_t width, int32_t height,
                               double antialias) {
  return guarded([&] {
    ft::pov::RenderOptions o;
    o.width = width;
    o.height = height;
    o.antialias = antialias;
    ft::pov::render_scene(path_arg("pov_path", pov_path), path_arg("out_png", out_png), o);
  });
}

}  // extern "C"
