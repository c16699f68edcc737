// The POV-Ray exporter behind the C ABI (fracterra/povray.h).
#include <cmath>
#include <memory>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "io/atomic_file.hpp"
#include "povray/heightfield_export.hpp"
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

}  // namespace

extern "C" {

FT_API ft_status ft_pov_scene_params_init(ft_pov_scene_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    const ft::pov::SceneParams d;
    *p = ft_pov_scene_params{};
    p->struct_size = sizeof(ft_pov_scene_params);
    p->world_size_x = d.world_size_x;
    p->world_size_y = d.world_size_y;
    p->vertical_scale = d.vertical_scale;
    p->camera_azimuth_deg = d.camera.azimuth_deg;
    p->camera_elevation_deg = d.camera.elevation_deg;
    p->camera_fov_deg = d.camera.fov_deg;
    p->camera_aspect = d.camera.aspect;
    p->camera_distance_scale = d.camera.distance_scale;
    p->sun_azimuth_deg = d.sun_azimuth_deg;
    p->sun_elevation_deg = d.sun_elevation_deg;
  });
}

FT_API ft_status ft_pov_write_scene(const ft_pov_scene_params* p, const char* pov_path) {
  return guarded([&] {
    ft::check_not_null("params", p);
    ft::check_struct_size(p->struct_size, sizeof(ft_pov_scene_params), "ft_pov_scene_params");
    const std::string path = path_arg("pov_path", pov_path);
    ft::check_int_range("line_set_count", p->line_set_count, 0, 1024);
    if (p->line_set_count > 0) ft::check_not_null("lines", p->lines);
    ft::pov::SceneParams s;
    if (p->terrain) s.terrain = &p->terrain->hf;
    s.world_size_x = p->world_size_x;
    s.world_size_y = p->world_size_y;
    s.vertical_scale = p->vertical_scale;
    s.has_sea = p->has_sea != 0;
    s.sea_level = p->sea_level;
    for (int32_t i = 0; i < p->line_set_count; ++i) {
      ft::check_not_null("lines[i].lines", p->lines[i].lines);
      s.lines.push_back({&p->lines[i].lines->set, ft::pov::LineKind(p->lines[i].kind), p->lines[i].radius});
    }
    s.camera.azimuth_deg = p->camera_azimuth_deg;
    s.camera.elevation_deg = p->camera_elevation_deg;
    s.camera.fov_deg = p->camera_fov_deg;
    s.camera.aspect = p->camera_aspect;
    s.camera.distance_scale = p->camera_distance_scale;
    s.sun_azimuth_deg = p->sun_azimuth_deg;
    s.sun_elevation_deg = p->sun_elevation_deg;
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
    std::unique_ptr<ft::AtomicFile> inc;
    std::string id;
    if (inc_path) {
      id = ft::pov::identifier(name ? name : "", "name");
      inc = std::make_unique<ft::AtomicFile>(path_arg("inc_path", inc_path));  // checks the folder first
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
    const ft::pov::SweepOptions d;
    *p = ft_pov_sweep_params{};
    p->struct_size = sizeof(ft_pov_sweep_params);
    p->spline = int32_t(d.spline);
    p->segments_per_sweep = d.segments_per_sweep;
    p->default_radius = d.default_radius;
    p->radius_scale = d.radius_scale;
    p->tolerance = d.tolerance;
  });
}

FT_API ft_status ft_pov_write_sweeps(const ft_polylines* lines, const ft_pov_sweep_params* p,
                                     const char* inc_path, const char* name) {
  return guarded([&] {
    ft::check_not_null("lines", lines);
    ft::check_not_null("params", p);
    ft::check_struct_size(p->struct_size, sizeof(ft_pov_sweep_params), "ft_pov_sweep_params");
    const std::string path = path_arg("inc_path", inc_path);
    const std::string id = ft::pov::identifier(name ? name : "", "name");
    ft::pov::SweepOptions o;
    o.spline = ft::pov::SweepSpline(p->spline);
    o.segments_per_sweep = p->segments_per_sweep;
    o.default_radius = p->default_radius;
    o.radius_scale = p->radius_scale;
    o.tolerance = p->tolerance;
    const std::string sdl = ft::pov::sweeps_sdl(lines->set, o);
    if (sdl.empty()) ft::invalid("the polyline set has no vertices");
    ft::write_file_atomically(path, "// fracterra polylines as chunked sphere_sweeps\n#declare " + id + " = " + sdl);
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
