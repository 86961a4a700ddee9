// Temporal caching's estimate of a record's hemisphere at the next frame by reprojection (the
// report's §4.3 and Figure 7; §5 "Reprojection of Incoming Radiance"): every hemisphere sample's
// hit point is carried with the motion of the triangle it lies on, its radiance with the change of
// the light it receives (tc_unshadowed.h), and the carried samples are put back into the
// record's hemisphere cells with a depth test (the nearest wins) and a 3 x 3 filter filling the
// cells none arrives in (the holes).
#pragma once

#include "caching/pipeline_shading.h"
#include "caching/radiance_hemisphere.h"
#include "shared/temporal.h"
#include "temporal/tc_unshadowed.h"

// The next frame's world triangles of the primitives that move: moved_slot[p] is primitive p's
// index into `triangles`, or -1 when p does not move.
typedef struct MovedTriangles {
    RC_GLOBAL const int* moved_slot;
    RC_GLOBAL const Triangle* triangles;
} MovedTriangles;

// Where local direction d (unit, z along the record normal) passes through the cells of an
// M x N record hemisphere of `layout` (shared/temporal.h), in continuous cell units: (row, column)
// = (M sin^2 theta, N phi / 2 pi) for irradiance caching's cosine-weighted cells
// (irradiance_records.h, rc_ic_cell_direction), (M (1 - cos theta), N phi / 2 pi) for radiance
// caching's uniform ones (caching/radiance_hemisphere.h); cell (j, k) holds [j, j + 1) x [k, k +
// 1).
RC_FUNC float2 rc_tc_cell_position(float3 d, int m, int n, int layout) {
    const float row = layout == RC_TC_CELLS_UNIFORM ? 1.0f - d.z : fmax(0.0f, 1.0f - d.z * d.z);
    float phi = atan2(d.y, d.x);
    if (phi < 0.0f) {
        phi += 2.0f * RC_PI;
    }
    return (float2)(row * (float)m, phi * (float)n / (2.0f * RC_PI));
}

// The cell direction d passes through; -1 below the hemisphere.
RC_FUNC int rc_tc_cell_of(float3 d, int m, int n, int layout) {
    if (!(d.z > 0.0f)) {
        return -1;
    }
    const float2 position = rc_tc_cell_position(d, m, n, layout);
    return min(m - 1, (int)position.x) * n + min(n - 1, (int)position.y);
}

// What places the jittered ray of each cell of one record's hemisphere: its cells' layout, the
// key of the random streams the jitter comes from and the record's stream.
typedef struct TcCellJitter {
    int m;
    int n;
    int layout;  // RC_TC_CELLS_COSINE or RC_TC_CELLS_UNIFORM
    uint key_lo;
    uint key_hi;
    uint record;
} TcCellJitter;

// The jitter (zeta, xi) of cell `cell`'s ray within the cell, in cell units: words 0 and 1 of the
// cell's stream for irradiance caching (rc_ic_cell_jitter); for radiance caching the row's polar
// and the column's azimuthal jitter of its jittered grid (rc_grid_stratum_direction).
RC_FUNC void rc_tc_cell_jitter(const TcCellJitter* jitter, int cell, float* zeta, float* xi) {
    if (jitter->layout == RC_TC_CELLS_UNIFORM) {
        const int row = cell / jitter->n;
        const int column = cell % jitter->n;
        float unused;
        rc_stratum_jitter(jitter->key_lo, jitter->key_hi, jitter->record, (uint)(row * jitter->n),
                          zeta, &unused);
        rc_stratum_jitter(jitter->key_lo, jitter->key_hi, jitter->record, (uint)column, &unused,
                          xi);
        return;
    }
    *zeta = rc_uint_to_unit_float(
        rc_rng_word(jitter->key_lo, jitter->key_hi, jitter->record, (uint)cell, 0u));
    *xi = rc_uint_to_unit_float(
        rc_rng_word(jitter->key_lo, jitter->key_hi, jitter->record, (uint)cell, 1u));
}

// The direction of cell `cell`'s ray in world space, in the frame of the record's normal
// (rc_ic_record_frame): the cell's jitter (rc_tc_cell_jitter) within irradiance caching's
// cosine-weighted strata (rc_ic_cell_direction, as rc_ic_cell_ray places it) or radiance caching's
// uniform ones (rc_uniform_stratum_direction, as rc_grid_stratum_direction places it).
RC_FUNC float3 rc_tc_cell_direction(const TcCellJitter* jitter, int cell, float3 normal) {
    float zeta, xi;
    rc_tc_cell_jitter(jitter, cell, &zeta, &xi);
    const int j = cell / jitter->n;
    const int k = cell % jitter->n;
    const float3 d = jitter->layout == RC_TC_CELLS_UNIFORM
                         ? rc_uniform_stratum_direction(j, k, jitter->m, jitter->n, zeta, xi)
                         : rc_ic_cell_direction(j, k, jitter->m, jitter->n, zeta, xi);
    const Frame frame = rc_ic_record_frame(normal);
    return rc_from_local(&frame, d);
}

// Whether the segment of `ray` from its origin to distance t_max meets the box [lower, upper]
// (slabs, widened by a small margin; an empty box, lower > upper, meets nothing).
RC_FUNC bool rc_tc_segment_meets_box(Ray ray, float t_max, float3 lower, float3 upper) {
    if (!(lower.x <= upper.x)) {
        return false;
    }
    const float3 margin = 1e-4f * (upper - lower) + (float3)(1e-6f);
    const float3 inverse = 1.0f / ray.direction.xyz;
    const float3 t0 = (lower - margin - ray.origin.xyz) * inverse;
    const float3 t1 = (upper + margin - ray.origin.xyz) * inverse;
    const float3 near = fmin(t0, t1);
    const float3 far = fmax(t0, t1);
    const float enter = fmax(fmax(near.x, near.y), fmax(near.z, 0.0f));
    const float leave = fmin(fmin(far.x, far.y), fmin(far.z, t_max * 1.0001f));
    return enter <= leave;
}

// The largest side, in cells, of a moved sample's square (rc_tc_assemble looks 1 cell around the
// cell it lands in).
#define RC_TC_MAX_SQUARE 2.0f

// The centre of the square a moved sample covers at the next frame, in continuous cell units
// (rc_tc_cell_position's): its own cell's centre (row j + 1/2, column k + 1/2 of cell `cell`),
// shifted by how far its hit point's direction moved through the cells, from `before` (its ray's
// local direction at this frame) to `after` (the local direction of the hit point's next
// position); the column's shift wrapped into [-N/2, N/2], the centre's column into [0, N). The
// report rasterises each reprojected point as a pixel-sized point on the next frame's grid (§5
// "Reprojection of Incoming Radiance", Figure 7(b), (c)): a point that did not move lands on its
// own pixel. The cells' rays here are jittered, and a square centred on the jittered ray takes a
// neighbour cell's ray whenever the two jitters lie within half a cell, whatever the motion; the
// carried cell takes its own cell's ray alone at zero motion and a neighbour's in proportion to
// the motion, so the change estimated through it (eqs. 7-8) has no floor from the jitter and
// shrinks with the motion.
RC_FUNC float2 rc_tc_carried_cell(float3 before, float3 after, int cell, int m, int n, int layout) {
    const float2 from = rc_tc_cell_position(before, m, n, layout);
    const float2 to = rc_tc_cell_position(after, m, n, layout);
    float shift = to.y - from.y;
    shift -= (float)n * round(shift / (float)n);
    float column = (float)(cell % n) + 0.5f + shift;
    column -= (float)n * floor(column / (float)n);
    return (float2)((float)(cell / n) + 0.5f + to.x - from.x, column);
}

// Sample `cell` of a record at `origin` (frame `frame`), whose ray `ray` saw (radiance, distance)
// at this frame, carried to the next frame. A miss stays in its cell with the environment's
// change; a hit on a still triangle keeps its cell and depth; a hit on a moving triangle moves
// with it (the same barycentric coordinates on the triangle's next position), unless it leaves the
// hemisphere or turns its back to the record; it covers its own cell carried by its motion
// (rc_tc_carried_cell), grown as its distance shrinks (the solid angle of the surface it stands
// for grows as the inverse square of the distance), up to RC_TC_MAX_SQUARE.
RC_FUNC TcCarriedSample rc_tc_carry_sample(const SceneData* scene, MovedTriangles moved,
                                           RC_GLOBAL const TcEmitter* now,
                                           RC_GLOBAL const TcEmitter* next, const TcParams* tc,
                                           int m, int n, Frame frame, float3 origin, int cell,
                                           Ray ray, float4 seen) {
    const int emitter_count = tc->emitter_count;
    TcCarriedSample s;
    s.pad0 = s.pad1 = s.pad2 = 0;
    s.cell = cell;
    s.depth = seen.w;
    s.row = s.column = s.size = 0.0f;
    s.radiance = (float4)(seen.xyz, 0.0f);
    if (tc->emitters_change == 0 &&
        !rc_tc_segment_meets_box(ray, seen.w, tc->moving_lower.xyz, tc->moving_upper.xyz)) {
        return s;  // still light on a still hit: carried as it is (what the steps below give)
    }
    const Hit hit = rc_trace_closest(scene->nodes, scene->triangles, ray);
    if (hit.primitive == RC_NO_HIT) {
        const float3 e0 = rc_tc_environment(now, emitter_count);
        const float3 e1 = rc_tc_environment(next, emitter_count);
        s.radiance = (float4)(rc_tc_carry_radiance(seen.xyz, (float3)(0.0f), e0, e1), 0.0f);
        s.depth = INFINITY;
        return s;
    }
    const SurfacePoint sp = rc_surface_point(scene, ray, hit);
    const float3 rho = rc_surface_material(scene, &sp).diffuse;
    const float3 e0 =
        rc_tc_unshadowed_irradiance(now, emitter_count, sp.position, sp.geometric_normal);
    float3 position = sp.position;
    float3 normal = sp.geometric_normal;
    const int slot = moved.moved_slot[hit.primitive];
    if (slot >= 0) {
        RC_GLOBAL const Triangle* t = moved.triangles + slot;
        position = rc_hit_point(t, hit.u, hit.v);
        normal = rc_triangle_normal(t);
        if (!sp.front) {
            normal = -normal;  // the side the ray saw
        }
        const float3 offset = position - origin;
        s.depth = length(offset);
        const float3 direction = rc_to_local(&frame, offset / s.depth);
        const bool faces = dot(normal, offset) < 0.0f && s.depth > 0.0f && direction.z > 0.0f;
        const float2 centre = rc_tc_carried_cell(rc_to_local(&frame, ray.direction.xyz), direction,
                                                 cell, m, n, tc->cell_layout);
        s.row = centre.x;
        s.column = centre.y;
        s.cell = faces ? min(m - 1, max(0, (int)floor(centre.x))) * n +
                             min(n - 1, max(0, (int)floor(centre.y)))
                       : -1;
        s.size = clamp(seen.w / s.depth, 1.0f, RC_TC_MAX_SQUARE);
    }
    const float3 e1 = rc_tc_unshadowed_irradiance(next, emitter_count, position, normal);
    s.radiance = (float4)(rc_tc_carry_radiance(seen.xyz, rho, e0, e1), 0.0f);
    return s;
}

// Marks of a cell while a record's next hemisphere is assembled (rc_tc_assemble): empty, holding
// the nearest carried sample that arrived in it, or filled by hole-filling pass p
// (RC_TC_FILLED_BY_PASS + p).
#define RC_TC_EMPTY 0xffffffffu
#define RC_TC_CARRIED 0u
#define RC_TC_FILLED_BY_PASS 1u

// Hole filling's depth classes: a neighbour is near when within this factor of the nearest one's
// distance, far when within its inverse of the farthest one's.
#define RC_TC_DEPTH_CLASS 1.1f

// Cell (j, k) of an M x N hemisphere, the azimuth wrapping around; -1 past the pole or the
// horizon.
RC_FUNC int rc_tc_neighbour(int j, int k, int m, int n) {
    return j < 0 || j >= m ? -1 : j * n + (k + n) % n;
}

// Whether a cell marked `mark` was filled before hole-filling pass `pass`.
RC_FUNC bool rc_tc_filled_before(uint mark, int pass) {
    return mark != RC_TC_EMPTY && mark < RC_TC_FILLED_BY_PASS + (uint)pass;
}

// The value hole-filling pass `pass` gives empty cell (j, k): from its 3 x 3 neighbours filled
// before the pass, the mean of one depth class (radiance averaged, distance by its inverse). A
// hole inside a surface that came nearer (its samples spread apart) is surrounded by it: when at
// least 5 of the 8 neighbours are near, the near ones; else the hole is background a moving
// occluder uncovered, and the far ones fill it. w = 0 when no neighbour is filled.
RC_FUNC float4 rc_tc_fill_hole(RC_GLOBAL const float4* out, RC_GLOBAL const uint* marks, int j,
                               int k, int m, int n, int pass) {
    float nearest = INFINITY;
    float farthest = 0.0f;
    int filled = 0;
    for (int dj = -1; dj <= 1; ++dj) {
        for (int dk = -1; dk <= 1; ++dk) {
            const int neighbour = rc_tc_neighbour(j + dj, k + dk, m, n);
            if (neighbour >= 0 && rc_tc_filled_before(marks[neighbour], pass)) {
                nearest = fmin(nearest, out[neighbour].w);
                farthest = fmax(farthest, out[neighbour].w);
                ++filled;
            }
        }
    }
    if (filled == 0) {
        return (float4)(0.0f);
    }
    int near_count = 0;
    for (int dj = -1; dj <= 1; ++dj) {
        for (int dk = -1; dk <= 1; ++dk) {
            const int neighbour = rc_tc_neighbour(j + dj, k + dk, m, n);
            if (neighbour >= 0 && rc_tc_filled_before(marks[neighbour], pass) &&
                out[neighbour].w <= RC_TC_DEPTH_CLASS * nearest) {
                ++near_count;
            }
        }
    }
    const bool take_near = near_count >= 5;
    float3 radiance = (float3)(0.0f);
    float inverse_depth = 0.0f;
    int count = 0;
    for (int dj = -1; dj <= 1; ++dj) {
        for (int dk = -1; dk <= 1; ++dk) {
            const int neighbour = rc_tc_neighbour(j + dj, k + dk, m, n);
            if (neighbour < 0 || !rc_tc_filled_before(marks[neighbour], pass)) {
                continue;
            }
            const float depth = out[neighbour].w;
            if (take_near ? depth <= RC_TC_DEPTH_CLASS * nearest
                          : depth * RC_TC_DEPTH_CLASS >= farthest) {
                radiance += out[neighbour].xyz;
                inverse_depth += 1.0f / depth;
                ++count;
            }
        }
    }
    return (float4)(radiance / (float)count,
                    inverse_depth > 0.0f ? (float)count / inverse_depth : INFINITY);
}

// A record's hemisphere (`jitter`: its cells and their jittered rays) at the next frame, as M N
// cells (L.rgb, distance) into out[], from its carried samples (`carried`, one per cell of this
// frame; marks[] is scratch of M N): a cell takes the nearest of the samples that cover its ray (a
// still sample its own cell's; a moved one, its square, rc_tc_carry_sample; the first in cell order
// on a tie), so that a moving surface neither grows nor shrinks by the cells its edge lands in;
// then up to hole_passes passes fill each empty cell from its 3 x 3 neighbourhood (azimuth wraps,
// rows do not; rc_tc_fill_hole) — the report's 3 x 3 filter, made to tell a gap in a surface
// that came nearer from background a moving occluder uncovered; a cell still empty keeps this
// frame's sample `seen`.
RC_FUNC void rc_tc_assemble(const TcCellJitter* jitter, int hole_passes,
                            RC_GLOBAL const TcCarriedSample* carried, RC_GLOBAL const float4* seen,
                            RC_GLOBAL float4* out, RC_GLOBAL uint* marks) {
    const int m = jitter->m;
    const int n = jitter->n;
    const int cells = m * n;
    for (int c = 0; c < cells; ++c) {
        marks[c] = RC_TC_EMPTY;
    }
    // Depth test: the samples that did not move into their own cells, then the moved ones in
    // cell order into every cell of the 3 x 3 around their landing cell whose ray (its jittered
    // direction) their square covers. A cell keeps the nearest.
    for (int c = 0; c < cells; ++c) {
        const TcCarriedSample s = carried[c];
        if (s.cell >= 0 && s.size == 0.0f) {
            out[c] = (float4)(s.radiance.xyz, s.depth);
            marks[c] = RC_TC_CARRIED;
        }
    }
    for (int c = 0; c < cells; ++c) {
        const TcCarriedSample s = carried[c];
        if (s.cell < 0 || s.size == 0.0f) {
            continue;
        }
        const int j = s.cell / n;
        const int k = s.cell % n;
        for (int dj = -1; dj <= 1; ++dj) {
            for (int dk = -1; dk <= 1; ++dk) {
                const int target = rc_tc_neighbour(j + dj, k + dk, m, n);
                if (target < 0 || (marks[target] == RC_TC_CARRIED && !(s.depth < out[target].w))) {
                    continue;
                }
                float zeta, xi;
                rc_tc_cell_jitter(jitter, target, &zeta, &xi);
                const float row = (float)(j + dj) + zeta;
                float column = (float)(k + dk) + xi - s.column;  // k + dk may leave [0, N)
                column -= (float)n * round(column / (float)n);   // the azimuth wraps
                if (fabs(row - s.row) <= 0.5f * s.size && fabs(column) <= 0.5f * s.size) {
                    out[target] = (float4)(s.radiance.xyz, s.depth);
                    marks[target] = RC_TC_CARRIED;
                }
            }
        }
    }
    // Hole filling: each pass reads only cells filled before it.
    for (int pass = 0; pass < hole_passes; ++pass) {
        bool any_empty = false;
        for (int c = 0; c < cells; ++c) {
            if (marks[c] != RC_TC_EMPTY) {
                continue;
            }
            const int j = c / n;
            const int k = c % n;
            const float4 fill = rc_tc_fill_hole(out, marks, j, k, m, n, pass);
            if (fill.w > 0.0f) {
                out[c] = fill;
                marks[c] = RC_TC_FILLED_BY_PASS + (uint)pass;
            } else {
                any_empty = true;
            }
        }
        if (!any_empty) {
            break;
        }
    }
    for (int c = 0; c < cells; ++c) {
        if (marks[c] == RC_TC_EMPTY) {
            out[c] = seen[c];
        }
    }
}
