#pragma once
// Procedural triangle meshes in object space (the caller places them with Mesh::transform).
// All are wound counter-clockwise seen from the side their normals point to, carry unit
// per-vertex normals and UVs, and keep spare position capacity for Accel (no copy).
// Bad parameters (non-positive or non-finite sizes, too few segments) throw InputError.

#include "renderer/geometry/mesh.h"

namespace ochre {

// Rectangle size.x by size.y centred at the origin in the xy plane, normal +z;
// uv in [0,1]^2 with u along +x and v along +y. 4 vertices, 2 triangles.
Mesh make_plane(Vec2 size);

// Disk of the given radius centred at the origin in the xy plane, normal +z, as a fan of
// `segments` (>= 3) triangles around a centre vertex; uv = ((x/r + 1)/2, (y/r + 1)/2).
// Its area is (segments/2) r^2 sin(2 pi/segments), i.e. pi r^2 to 0.01 % at 256 segments.
Mesh make_disk(float radius, int segments = 64);

// UV sphere centred at the origin with poles on the z axis: `subdivisions` (>= 2) bands of
// latitude and 2 * subdivisions of longitude. Normals are exactly position / radius (smooth
// shading). uv = (phi / 2pi, theta / pi) with phi = atan2(y, x) in [0, 2pi) and theta the polar
// angle measured from the south pole (-z), so v = 0 at z = -r and v = 1 at z = +r and an
// equirectangular image appears upright. The u = 1 seam and the poles use duplicated vertices
// with bit-identical positions, so the surface is watertight.
Mesh make_sphere(float radius, int subdivisions);

// Box size.x by size.y by size.z centred at the origin, 24 vertices (flat faces), 12 triangles, normals
// outward. The faces, their winding and their uvs are those of Mitsuba 3's cube (each face maps [0,1]^2)
// with v measured upward (v_ochre = 1 - v_Mitsuba), so an image appears on each face as in Mitsuba.
Mesh make_cube(Vec3 size);

// Open cone (a frustum when top_radius > 0) about z from z = 0 (radius `radius`) to z = height (radius
// `top_radius`, 0 for a pointed cone), without caps: `segments` (>= 3) quads around, flat along the slant
// and smooth around it (the normal of the exact cone at each vertex's angle); u = angle / 2pi (counter-
// clockwise about +z), v = z / height. 2 x segments triangles (segments for a pointed cone).
Mesh make_cone(float radius, float top_radius, float height, int segments);

// Reverses every triangle's winding and negates the normals: the surface faces the other way (which
// side emits, where a dielectric's outside is).
void flip_normals(Mesh& mesh);
// v -> 1 - v for every uv.
void flip_uv_v(Mesh& mesh);

// Triangles of make_sphere(radius, subdivisions), and the peak memory of building them with their BVH
// (renderer/util/memory_budget.h), checked before a scene asks for a sphere.
double sphere_triangle_count(int subdivisions);
double sphere_memory_bytes(int subdivisions);
// Triangles of make_cone.
double cone_triangle_count(int segments, bool pointed);

}  // namespace ochre
