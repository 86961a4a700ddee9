// Procedural meshes and scenes for tests and benchmarks.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "scene/scene.h"
#include "scene/triangle_mesh.h"

namespace rc {

// A closed sphere: the icosahedron subdivided `subdivisions` times (20 * 4^s triangles), every
// edge shared by exactly two triangles with shared vertex indices. `bump` > 0 displaces the
// radius by bump * sin(kx) sin(ky) sin(kz) (k = `bump_frequency`), keeping the mesh closed.
TriangleMesh make_icosphere(glm::vec3 center, float radius, int subdivisions, float bump = 0.0f,
                            float bump_frequency = 0.0f);

// `count` independent random triangles with vertices within `max_edge` of a centre drawn
// uniformly in the box [lower, upper] (the counter-based RNG with `seed`).
TriangleMesh make_triangle_soup(size_t count, uint32_t seed, glm::vec3 lower, glm::vec3 upper,
                                float max_edge);

// The parallelogram corner, corner + edge1, corner + edge1 + edge2, corner + edge2.
TriangleMesh make_quad(glm::vec3 corner, glm::vec3 edge1, glm::vec3 edge2);

// The built-in shapes of scene files (as Mitsuba's rectangle, cube and sphere):
// [-1, 1]^2 in the z = 0 plane facing +z, with uvs (0, 0) to (1, 1);
TriangleMesh make_rectangle();
// [-1, 1]^3 with outward faces, each face with uvs (0, 0) to (1, 1);
TriangleMesh make_cube();
// a closed latitude-longitude sphere with smooth normals and uvs (u around the z axis, v from the
// south pole); seam and pole vertices coincide exactly, so it is watertight.
TriangleMesh make_uv_sphere(glm::vec3 centre, float radius, int rings = 48, int segments = 96);

// The benchmark's dense scene: a side x side grid of bumpy icospheres (subdivision s) on a
// ground quad, seen from above at an angle. side = 5, s = 5 gives 512 002 triangles.
Scene make_sphere_grid_scene(int side = 5, int subdivisions = 5);

}  // namespace rc
