#pragma once
// Explicit groove geometry (object space; the caller places it with Mesh::transform), for comparing
// explicit microgeometry with the analytic `vgroove` material (docs/materials/vgroove.md):
// - a plate of parallel V-grooves: grooves along x, ridges at z = 0, valleys at depth
//   (pitch / 2) / tan(alpha / 2), `count` grooves side by side across y (centred), `length` along x;
// - a cylinder about the z axis (the smooth surface to carry the analytic material), and the same
//   cylinder with circumferential V-grooves cut into it (ridges at the radius), so the groove direction
//   turns around the surface.
// Facets are flat: each carries its own vertices with the facet's normal (shared edges have
// bit-identical positions). uv: u along the grooves (so dp/du is the groove direction), v across.

#include "renderer/geometry/mesh.h"

namespace ochre {

// The depth of a V-groove of the given width and dihedral angle: (pitch / 2) / tan(alpha / 2).
double groove_depth(double pitch, double alpha_degrees);

struct GroovePlate {
  float alpha_degrees = 90;  // dihedral angle, (0, 180)
  float pitch = 1;           // groove width across
  int count = 40;            // grooves
  float length = 40;         // along the grooves
  // Facets are cut along the grooves into tiles at most this many pitches long (0: one strip as long as
  // the plate). The image does not depend on it (docs/architecture.md, "Spawning rays"); short pieces give
  // the BVH compact boxes.
  float tile_pitches = 8;
};
// Tiles along the grooves of each facet.
double groove_plate_tiles(const GroovePlate& plate);
Mesh make_groove_plate(const GroovePlate& plate);

// Open tube of the given radius from z = 0 to z = height, smooth normals, u = angle / 2pi (counter-
// clockwise about +z), v = z / height.
Mesh make_cylinder(float radius, float height, int segments);

struct GroovedCylinder {
  float radius = 1;          // at the ridges
  float height = 1;          // z from 0 to height, holding floor(height / pitch) grooves
  float alpha_degrees = 90;  // dihedral angle of the grooves, (0, 180)
  float pitch = 0.05f;       // groove width along z
  int segments = 256;        // around the axis
};
Mesh make_grooved_cylinder(const GroovedCylinder& cylinder);

// Triangles of each shape (doubles: no count overflows), for the memory estimate checked before a scene
// asks for one (renderer/util/memory_budget.h).
double groove_plate_triangle_count(const GroovePlate& plate);      // 4 x count x tiles
double cylinder_triangle_count(int segments);                      // 2 x segments
double grooved_cylinder_triangle_count(const GroovedCylinder& c);  // 4 x grooves x segments
// The grooves of a grooved cylinder: floor(height / pitch), at least 1.
double groove_count(const GroovedCylinder& c);

}  // namespace ochre
