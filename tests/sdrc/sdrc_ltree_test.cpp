// SDRC's L-tree (kernels/shared/sdrc.h, kernels/sdrc/ltree.h, host/methods/sdrc/ltree.h) against
// oracles written from the documented formats, never from the code under test: the device's
// range query against a brute-force scan of the record's nodes, the host build against the
// kd-tree invariant of median order, insertion and rebuilds against the samples inserted, and the
// encodings (paraboloid map, RGBE) against their closed forms. Device items run
// kernels/sdrc/sdrc_probe.cl.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "methods/sdrc/ltree.h"
#include "shared/sdrc.h"
#include "test_support.h"

namespace rc {
namespace {

using shared::LTreeNode;
using shared::SdrcTree;

// The documented node format (kernels/shared/sdrc.h): bits 0-7 the u cell, 8-15 the v cell of a
// 256 x 256 grid over [-1, 1]^2, bit 16 the split axis, bit 17 "empty".
constexpr uint32_t kGrid = 256;
constexpr uint32_t kAxisBit = 1u << 16;
constexpr uint32_t kEmptyBit = 1u << 17;
static_assert(RC_LTREE_GRID == kGrid);
static_assert((1u << RC_LTREE_AXIS_SHIFT) == kAxisBit);
static_assert(RC_LTREE_EMPTY == kEmptyBit);

uint32_t cell_u(const LTreeNode& n) { return n.position & 0xffu; }
uint32_t cell_v(const LTreeNode& n) { return (n.position >> 8) & 0xffu; }
uint32_t cell(const LTreeNode& n, int axis) { return axis == 0 ? cell_u(n) : cell_v(n); }
bool is_empty(const LTreeNode& n) { return (n.position & kEmptyBit) != 0; }
// A cell's centre in D: (cell + 0.5) 2 / 256 - 1.
double centre(uint32_t c) { return (c + 0.5) * 2.0 / kGrid - 1.0; }

LTreeNode make_node(uint32_t u, uint32_t v, uint32_t radiance, bool empty = false) {
    LTreeNode n;
    n.radiance = radiance;
    n.position = u | v << 8 | (empty ? kEmptyBit : 0u);
    return n;
}

// A node as what identifies its sample: the cell and the radiance (bookkeeping bits aside).
std::tuple<uint32_t, uint32_t, uint32_t> sample_key(const LTreeNode& n) {
    return {cell_u(n), cell_v(n), n.radiance};
}

// Ward's RGBE word r | g << 8 | b << 16 | e << 24 as RGB: (byte + 0.5) 2^(e - 128 - 8), black
// when e is 0 (Ward, "Real Pixels"; the format kernels/shared/sdrc.h documents).
std::array<double, 3> decode_rgbe(uint32_t word) {
    const int e = static_cast<int>(word >> 24);
    if (e == 0) {
        return {0.0, 0.0, 0.0};
    }
    std::array<double, 3> rgb;
    for (int k = 0; k < 3; ++k) {
        rgb[k] = std::ldexp(static_cast<double>((word >> (8 * k)) & 255u) + 0.5, e - 136);
    }
    return rgb;
}

// A random RGBE word of moderate magnitude (channels up to 2^8).
uint32_t random_radiance(std::mt19937& rng) {
    std::uniform_int_distribution<uint32_t> byte(0, 255), exponent(120, 136);
    return byte(rng) | byte(rng) << 8 | byte(rng) << 16 | exponent(rng) << 24;
}

enum class Layout { kUniform, kClustered, kDuplicates, kLine };
const Layout kLayouts[] = {Layout::kUniform, Layout::kClustered, Layout::kDuplicates,
                           Layout::kLine};
const char* layout_name(Layout layout) {
    switch (layout) {
        case Layout::kUniform:
            return "uniform";
        case Layout::kClustered:
            return "clustered";
        case Layout::kDuplicates:
            return "duplicates";
        case Layout::kLine:
            return "line";
    }
    return "?";
}

// `count` random samples in `layout`, a fraction `empty` of them empty: uniform cells; a few
// tight clusters (clipped to the grid's edges); cells (and whole nodes) drawn from a small pool;
// all on one row or column of the grid.
std::vector<LTreeNode> random_samples(std::mt19937& rng, size_t count, Layout layout,
                                      double empty = 0.0) {
    std::uniform_int_distribution<uint32_t> any_cell(0, kGrid - 1);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<LTreeNode> pool;
    for (size_t k = 0; k < std::max<size_t>(1, count / 8); ++k) {
        pool.push_back(make_node(any_cell(rng), any_cell(rng), random_radiance(rng)));
    }
    std::vector<std::array<double, 3>> clusters;  // u, v, sigma (cells)
    for (int k = 0; k < 1 + static_cast<int>(uniform(rng) * 4); ++k) {
        clusters.push_back({uniform(rng) * kGrid, uniform(rng) * kGrid, 6.0 * uniform(rng)});
    }
    const bool line_is_row = uniform(rng) < 0.5;
    const uint32_t line = any_cell(rng);
    std::normal_distribution<double> normal(0.0, 1.0);
    auto clip = [](double x) {
        return static_cast<uint32_t>(std::clamp(std::floor(x), 0.0, kGrid - 1.0));
    };
    std::vector<LTreeNode> samples;
    for (size_t k = 0; k < count; ++k) {
        LTreeNode n;
        switch (layout) {
            case Layout::kUniform:
                n = make_node(any_cell(rng), any_cell(rng), random_radiance(rng));
                break;
            case Layout::kClustered: {
                const auto& c = clusters[rng() % clusters.size()];
                n = make_node(clip(c[0] + c[2] * normal(rng)), clip(c[1] + c[2] * normal(rng)),
                              random_radiance(rng));
                break;
            }
            case Layout::kDuplicates:
                n = pool[rng() % pool.size()];
                if (uniform(rng) < 0.5) {
                    n.radiance = random_radiance(rng);  // same cell, other radiance
                }
                break;
            case Layout::kLine:
                n = line_is_row ? make_node(any_cell(rng), line, random_radiance(rng))
                                : make_node(line, any_cell(rng), random_radiance(rng));
                break;
        }
        if (uniform(rng) < empty) {
            n.position |= kEmptyBit;
        }
        samples.push_back(n);
    }
    return samples;
}

// ---------------------------------------------------------------------------------------------
// The device range query.

struct QueryResult {
    uint32_t count = 0;
    shared::float4 sums{};          // xyz: sum w L; w: sum w
    std::vector<uint32_t> indices;  // the first min(count, capacity) found
};

// Query q of record records[q] at queries[q] (u, v, radius) by sdrc_query_probe.
std::vector<QueryResult> device_queries(const PackedLTrees& packed,
                                        const std::vector<uint32_t>& records,
                                        const std::vector<shared::float4>& queries,
                                        uint32_t capacity) {
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("sdrc/sdrc_probe.cl", "sdrc_query_probe");
    std::vector<LTreeNode> nodes = packed.nodes;
    if (nodes.empty()) {
        nodes.push_back(make_node(0, 0, 0, true));  // no zero-size buffer; never addressed
    }
    const Buffer<LTreeNode> node_buffer(context, nodes, "nodes");
    const Buffer<SdrcTree> tree_buffer(context, packed.trees, "trees");
    const Buffer<uint32_t> record_buffer(context, records, "records");
    const Buffer<shared::float4> query_buffer(context, queries, "queries");
    Buffer<uint32_t> counts(context, queries.size(), "counts");
    Buffer<shared::float4> sums(context, queries.size(), "sums");
    Buffer<uint32_t> found(context, queries.size() * std::max<uint32_t>(capacity, 1), "found");
    counts.fill_zero();
    sums.fill_zero();
    found.fill_zero();
    context.launch(kernel, queries.size(), node_buffer, tree_buffer, record_buffer, query_buffer,
                   capacity, counts, sums, found);
    const std::vector<uint32_t> c = counts.download();
    const std::vector<shared::float4> s = sums.download();
    const std::vector<uint32_t> f = found.download();
    std::vector<QueryResult> results(queries.size());
    for (size_t q = 0; q < queries.size(); ++q) {
        results[q].count = c[q];
        results[q].sums = s[q];
        const size_t stored = std::min(c[q], capacity);
        results[q].indices.assign(f.begin() + q * capacity, f.begin() + q * capacity + stored);
    }
    return results;
}

// What a brute-force scan of one record's nodes (tree and buffer) finds at a query: a node is
// found iff its cell centre lies strictly within the radius, with weight 1 - d^2 / r^2. Nodes
// whose d^2 lies within a relative `band` of r^2 are `ambiguous` (float rounding may put them on
// either side): the device may or may not find them, and their weights are below `band`. On the
// grid (query at a cell centre, radius a multiple of half a cell) d^2 and r^2 are exact in float
// and double alike, so band 0 leaves nothing ambiguous, ties (d^2 = r^2) included.
struct Expected {
    std::vector<uint32_t> found;      // sorted
    std::vector<uint32_t> ambiguous;  // sorted
    size_t ties = 0;                  // nodes at exactly d^2 = r^2
    std::array<double, 4> sums{};     // rgb, weight of `found`
    // The sums' tolerance: float rounding of the weights (1e-6 absolute each) and of the
    // sums (1e-5 relative), and the ambiguous nodes' weights.
    double tolerance = 1e-6;
};

Expected brute_force(const std::vector<LTreeNode>& nodes, const SdrcTree& tree,
                     const shared::float4& query, double band) {
    Expected e;
    const double u = query.x, v = query.y, r = query.z;
    const double r2 = r * r;
    for (uint32_t i = 0; i < tree.tree_nodes + tree.buffer_nodes; ++i) {
        const LTreeNode& n = nodes[tree.first_node + i];
        if (is_empty(n)) {
            continue;
        }
        const double du = centre(cell_u(n)) - u, dv = centre(cell_v(n)) - v;
        const double d2 = du * du + dv * dv;
        const std::array<double, 3> rgb = decode_rgbe(n.radiance);
        const double largest = std::max({rgb[0], rgb[1], rgb[2], 1.0});
        e.ties += d2 == r2 ? 1 : 0;
        if (band > 0.0 && std::abs(d2 - r2) <= band * r2) {
            e.ambiguous.push_back(i);
            e.tolerance += 2.0 * band * largest;
        } else if (d2 < r2) {
            e.found.push_back(i);
            const double w = 1.0 - d2 / r2;
            for (int k = 0; k < 3; ++k) {
                e.sums[k] += w * rgb[k];
            }
            e.sums[3] += w;
            e.tolerance += (1e-5 * w + 2e-6) * largest;
        }
    }
    return e;
}

// Random queries of one record: anywhere in [-1.1, 1.1]^2, or near one of its nodes, or one
// radius (times 1 - 1e-3, 1 + 1e-3 or exactly) along an axis from one, where the split planes
// prune; radii log-uniform in [1e-3, 0.6].
std::vector<shared::float4> random_queries(std::mt19937& rng, const std::vector<LTreeNode>& nodes,
                                           const SdrcTree& tree, int count) {
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const uint32_t size = tree.tree_nodes + tree.buffer_nodes;
    std::vector<shared::float4> queries;
    for (int k = 0; k < count; ++k) {
        const float radius = static_cast<float>(1e-3 * std::pow(600.0, uniform(rng)));
        float u = static_cast<float>(-1.1 + 2.2 * uniform(rng));
        float v = static_cast<float>(-1.1 + 2.2 * uniform(rng));
        const double kind = uniform(rng);
        if (size > 0 && kind < 0.5) {
            const LTreeNode& n = nodes[tree.first_node + rng() % size];
            const double cu = centre(cell_u(n)), cv = centre(cell_v(n));
            if (kind < 0.25) {
                u = static_cast<float>(cu + 0.01 * (uniform(rng) - 0.5));
                v = static_cast<float>(cv + 0.01 * (uniform(rng) - 0.5));
            } else {
                const double edge =
                    kind < 0.3 ? 1.0 : (uniform(rng) < 0.5 ? 1.0 - 1e-3 : 1.0 + 1e-3);
                const double offset = (uniform(rng) < 0.5 ? -1.0 : 1.0) * edge * radius;
                const bool along_u = uniform(rng) < 0.5;
                u = static_cast<float>(cu + (along_u ? offset : 0.0));
                v = static_cast<float>(cv + (along_u ? 0.0 : offset));
            }
        }
        queries.push_back({u, v, radius, 0.0f});
    }
    return queries;
}

// Tallies of check_queries, which checks every device result against the brute force and
// reports the first 10 failures.
struct QueryStats {
    size_t queries = 0, nonempty = 0, found = 0, ambiguous = 0, ties = 0, failures = 0;
};

void check_queries(const PackedLTrees& packed, const std::vector<uint32_t>& records,
                   const std::vector<shared::float4>& queries,
                   const std::vector<std::string>& labels, double band, QueryStats* stats) {
    uint32_t capacity = 1;
    for (const SdrcTree& t : packed.trees) {
        capacity = std::max(capacity, t.tree_nodes + t.buffer_nodes);
    }
    const std::vector<QueryResult> results = device_queries(packed, records, queries, capacity);
    for (size_t q = 0; q < queries.size(); ++q) {
        const SdrcTree& tree = packed.trees[records[q]];
        const Expected e = brute_force(packed.nodes, tree, queries[q], band);
        const QueryResult& r = results[q];
        std::vector<uint32_t> got = r.indices;
        std::sort(got.begin(), got.end());
        std::vector<uint32_t> missing, extra;
        std::set_difference(e.found.begin(), e.found.end(), got.begin(), got.end(),
                            std::back_inserter(missing));
        for (uint32_t i : got) {
            if (!std::binary_search(e.found.begin(), e.found.end(), i) &&
                !std::binary_search(e.ambiguous.begin(), e.ambiguous.end(), i)) {
                extra.push_back(i);
            }
        }
        const bool duplicates = std::adjacent_find(got.begin(), got.end()) != got.end();
        const double device_sums[4] = {r.sums.x, r.sums.y, r.sums.z, r.sums.w};
        bool sums_ok = true;
        for (int k = 0; k < 4; ++k) {
            sums_ok = sums_ok && std::abs(device_sums[k] - e.sums[k]) <= e.tolerance;
        }
        const bool ok = r.count == got.size() && r.count <= capacity && missing.empty() &&
                        extra.empty() && !duplicates && sums_ok;
        stats->queries += 1;
        stats->nonempty += e.found.empty() ? 0 : 1;
        stats->found += e.found.size();
        stats->ambiguous += e.ambiguous.size();
        stats->ties += e.ties;
        if (!ok && ++stats->failures <= 10) {
            ADD_FAILURE() << labels[q] << ": query (" << queries[q].x << ", " << queries[q].y
                          << ") radius " << queries[q].z << " of a record of " << tree.tree_nodes
                          << " tree + " << tree.buffer_nodes << " buffer nodes: device count "
                          << r.count << ", expected " << e.found.size() << " (+"
                          << e.ambiguous.size() << " ambiguous); " << missing.size()
                          << " missing (first "
                          << (missing.empty() ? -1 : static_cast<int64_t>(missing[0])) << "), "
                          << extra.size() << " extra, duplicates " << duplicates << "; weight "
                          << r.sums.w << " vs " << e.sums[3] << ", rgb (" << r.sums.x << ", "
                          << r.sums.y << ", " << r.sums.z << ") vs (" << e.sums[0] << ", "
                          << e.sums[1] << ", " << e.sums[2] << ")";
        }
    }
}

// Records of `size` samples: 3 trees of each layout (two with a buffer of samples beside them,
// some of which are empty; one built from samples some of which are empty), packed together so
// that records start anywhere in the node array.
struct Records {
    PackedLTrees packed;
    std::vector<std::string> names;
};

Records random_records(std::mt19937& rng, size_t size) {
    std::vector<LTree> trees;
    Records records;
    for (Layout layout : kLayouts) {
        for (int k = 0; k < 3; ++k) {
            LTree t;
            t.tree = random_samples(rng, size, layout, k == 2 ? 0.1 : 0.0);
            build_ltree(&t.tree);
            if (k > 0) {
                t.buffer = random_samples(rng, 1 + rng() % 40, layout, 0.2);
            }
            trees.push_back(std::move(t));
            records.names.push_back(std::string(layout_name(layout)) + " " + std::to_string(size) +
                                    (k > 0 ? " with buffer" : ""));
        }
    }
    records.packed = pack_ltrees(trees);
    return records;
}

const size_t kSizes[] = {0, 1, 2, 3, 7, 100, 5000};

// Random records of every size (kSizes), each queried at `queries_of(packed, its tree)`, the
// answers checked against the brute force (check_queries, within `band`): the tallies.
template <class QueriesOf>
QueryStats query_records_of_every_size(std::mt19937& rng, double band,
                                       const QueriesOf& queries_of) {
    QueryStats stats;
    for (size_t size : kSizes) {
        const Records r = random_records(rng, size);
        std::vector<uint32_t> records;
        std::vector<shared::float4> queries;
        std::vector<std::string> labels;
        for (uint32_t i = 0; i < r.packed.trees.size(); ++i) {
            for (const shared::float4& q : queries_of(r.packed, r.packed.trees[i])) {
                records.push_back(i);
                queries.push_back(q);
                labels.push_back(r.names[i]);
            }
        }
        check_queries(r.packed, records, queries, labels, band, &stats);
    }
    return stats;
}

// Every record of every size queried 96 times at random (random_queries); every answer is the
// brute force's.
TEST(SdrcLTree, RangeQueryFindsExactlyTheBruteForceSet) {
    std::mt19937 rng(2009);
    const QueryStats stats = query_records_of_every_size(
        rng, 1e-5, [&](const PackedLTrees& packed, const SdrcTree& tree) {
            return random_queries(rng, packed.nodes, tree, 96);
        });
    EXPECT_EQ(stats.failures, 0u) << "of " << stats.queries << " queries";
    // Not vacuous: many queries find something, and ambiguity is rare.
    EXPECT_GT(stats.nonempty, stats.queries / 4);
    EXPECT_GT(stats.found, 50000u);
    EXPECT_LT(stats.ambiguous * 10, stats.found);
    std::printf("%zu queries, %zu finding samples, %zu samples found, %zu ambiguous\n",
                stats.queries, stats.nonempty, stats.found, stats.ambiguous);
}

// Queries on the grid: at cell centres (some beyond the grid, some at a node's cell), radii
// h / 256 for h = 0 .. 154 (multiples of half a cell, 0 to 0.6), where the distances are exact:
// the device finds exactly the nodes strictly within, never one exactly on the circle.
TEST(SdrcLTree, RangeQueryIsExactOnTheGrid) {
    std::mt19937 rng(1998);
    std::uniform_int_distribution<int> any_cell(-8, kGrid + 7), half_cells(0, 154);
    const QueryStats stats = query_records_of_every_size(
        rng, 0.0, [&](const PackedLTrees& packed, const SdrcTree& tree) {
            const uint32_t nodes = tree.tree_nodes + tree.buffer_nodes;
            std::vector<shared::float4> queries;
            for (int k = 0; k < 64; ++k) {
                int cu = any_cell(rng), cv = any_cell(rng);
                if (nodes > 0 && k % 2 == 0) {
                    const LTreeNode& n = packed.nodes[tree.first_node + rng() % nodes];
                    cu = static_cast<int>(cell_u(n));
                    cv = static_cast<int>(cell_v(n));
                }
                queries.push_back({static_cast<float>((cu + 0.5) * 2.0 / kGrid - 1.0),
                                   static_cast<float>((cv + 0.5) * 2.0 / kGrid - 1.0),
                                   static_cast<float>(half_cells(rng) / 256.0), 0.0f});
            }
            return queries;
        });
    EXPECT_EQ(stats.failures, 0u) << "of " << stats.queries << " queries";
    EXPECT_EQ(stats.ambiguous, 0u);
    EXPECT_GT(stats.nonempty, stats.queries / 4);
    EXPECT_GT(stats.ties, 1000u);  // nodes exactly on the circle, which must not be found
    std::printf("%zu queries, %zu finding samples, %zu samples found, %zu on the circle\n",
                stats.queries, stats.nonempty, stats.found, stats.ties);
}

// ---------------------------------------------------------------------------------------------
// The host build.

// Whether nodes[lo, hi) is a kd-tree in median order: the node at lo + (hi - lo) / 2 has every
// node of [lo, mid) at or below its cell along its axis bit and every node of (mid, hi) at or
// above, and so on down; its axis is that of the range's larger extent in cells (u on a tie), as
// build_ltree documents. Reports the first violation.
::testing::AssertionResult is_kd_tree(const std::vector<LTreeNode>& nodes, size_t lo, size_t hi) {
    if (hi - lo <= 1) {
        return ::testing::AssertionSuccess();
    }
    const size_t mid = lo + (hi - lo) / 2;
    const int axis = (nodes[mid].position & kAxisBit) != 0 ? 1 : 0;
    const uint32_t split = cell(nodes[mid], axis);
    uint32_t low[2] = {kGrid, kGrid}, high[2] = {0, 0};
    for (size_t i = lo; i < hi; ++i) {
        for (int a = 0; a < 2; ++a) {
            low[a] = std::min(low[a], cell(nodes[i], a));
            high[a] = std::max(high[a], cell(nodes[i], a));
        }
    }
    const int larger = high[1] - low[1] > high[0] - low[0] ? 1 : 0;
    if (axis != larger) {
        return ::testing::AssertionFailure()
               << "range [" << lo << ", " << hi << ") extends " << high[0] - low[0]
               << " cells in u, " << high[1] - low[1] << " in v, split along " << axis;
    }
    for (size_t i = lo; i < hi; ++i) {
        const uint32_t c = cell(nodes[i], axis);
        if ((i < mid && c > split) || (i > mid && c < split)) {
            return ::testing::AssertionFailure()
                   << "range [" << lo << ", " << hi << "): node " << i << " has cell " << c
                   << " along axis " << axis << " on the wrong side of the median's " << split;
        }
    }
    ::testing::AssertionResult left = is_kd_tree(nodes, lo, mid);
    if (!left) {
        return left;
    }
    return is_kd_tree(nodes, mid + 1, hi);
}

std::multiset<std::tuple<uint32_t, uint32_t, uint32_t>> nonempty_samples(
    const std::vector<LTreeNode>& nodes) {
    std::multiset<std::tuple<uint32_t, uint32_t, uint32_t>> samples;
    for (const LTreeNode& n : nodes) {
        if (!is_empty(n)) {
            samples.insert(sample_key(n));
        }
    }
    return samples;
}

TEST(SdrcLTree, BuildIsAKdTreeOfTheNonEmptySamples) {
    std::mt19937 rng(17);
    for (size_t size : {0, 1, 2, 3, 7, 100, 5000}) {
        for (Layout layout : kLayouts) {
            for (double empty : {0.0, 0.3, 1.0}) {
                SCOPED_TRACE(std::string(layout_name(layout)) + " " + std::to_string(size) +
                             " samples, empty fraction " + std::to_string(empty));
                const std::vector<LTreeNode> input = random_samples(rng, size, layout, empty);
                std::vector<LTreeNode> nodes = input;
                build_ltree(&nodes);
                for (const LTreeNode& n : nodes) {
                    ASSERT_FALSE(is_empty(n));
                }
                EXPECT_EQ(nonempty_samples(nodes), nonempty_samples(input));
                EXPECT_TRUE(is_kd_tree(nodes, 0, nodes.size()));
            }
        }
    }
}

// Building the same samples twice, a shuffled copy of them, and the built tree itself (as a
// rebuild does) gives the identical node array.
TEST(SdrcLTree, BuildIsDeterministic) {
    std::mt19937 rng(23);
    auto same = [](const std::vector<LTreeNode>& a, const std::vector<LTreeNode>& b) {
        return a.size() == b.size() &&
               (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(LTreeNode)) == 0);
    };
    for (size_t size : {0, 1, 2, 3, 7, 100, 5000}) {
        for (Layout layout : kLayouts) {
            SCOPED_TRACE(std::string(layout_name(layout)) + " " + std::to_string(size));
            const std::vector<LTreeNode> input = random_samples(rng, size, layout, 0.1);
            std::vector<LTreeNode> first = input, second = input, shuffled = input;
            build_ltree(&first);
            build_ltree(&second);
            EXPECT_TRUE(same(first, second));
            std::shuffle(shuffled.begin(), shuffled.end(), rng);
            build_ltree(&shuffled);
            EXPECT_TRUE(same(first, shuffled));
            std::vector<LTreeNode> rebuilt = first;
            std::shuffle(rebuilt.begin(), rebuilt.end(), rng);
            build_ltree(&rebuilt);
            EXPECT_TRUE(same(first, rebuilt));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Insertion and rebuilds.

// Samples inserted one at a time into L-trees with buffers of 1, 2, 5 and 64 samples: after each
// insertion the tree has been rebuilt floor(inserted / capacity) times and holds the non-empty
// samples of those rebuilds, the buffer the rest; at the checkpoints, a query of radius 1e-3 (an
// eighth of a cell) at every inserted sample's cell centre finds exactly the non-empty samples
// inserted in that cell (their radiances, each at weight 1) on the device, and one of radius 2 at
// the origin (all of D) finds every non-empty sample inserted.
TEST(SdrcLTree, InsertionAndRebuildsKeepEverySampleFindable) {
    std::mt19937 rng(5);
    const std::vector<size_t> capacities = {1, 2, 5, 64};
    const size_t total = 400;
    std::vector<LTreeNode> samples = random_samples(rng, total / 2, Layout::kUniform, 0.1);
    const std::vector<LTreeNode> clustered =
        random_samples(rng, total / 2, Layout::kClustered, 0.1);
    samples.insert(samples.end(), clustered.begin(), clustered.end());
    std::vector<LTree> trees(capacities.size());
    const std::vector<size_t> checkpoints = {1, 2, 4, 5, 6, 63, 64, 65, 130, 257, total};
    size_t checked = 0;
    for (size_t inserted = 1; inserted <= total; ++inserted) {
        const LTreeNode& sample = samples[inserted - 1];
        size_t nonempty_rebuilt[4] = {};
        for (size_t t = 0; t < trees.size(); ++t) {
            trees[t].insert(sample, capacities[t]);
            const size_t rebuilds = inserted / capacities[t];
            ASSERT_EQ(trees[t].rebuilds, rebuilds) << "capacity " << capacities[t];
            ASSERT_EQ(trees[t].buffer.size(), inserted - rebuilds * capacities[t]);
            for (size_t k = 0; k < rebuilds * capacities[t]; ++k) {
                nonempty_rebuilt[t] += is_empty(samples[k]) ? 0 : 1;
            }
            ASSERT_EQ(trees[t].tree.size(), nonempty_rebuilt[t]) << "capacity " << capacities[t];
        }
        if (std::find(checkpoints.begin(), checkpoints.end(), inserted) == checkpoints.end()) {
            continue;
        }
        // Expected per cell: the radiances of the non-empty samples inserted so far.
        std::map<uint32_t, std::multiset<uint32_t>> by_cell;
        std::multiset<std::tuple<uint32_t, uint32_t, uint32_t>> all;
        std::vector<uint32_t> cells;
        for (size_t k = 0; k < inserted; ++k) {
            const uint32_t c = samples[k].position & 0xffffu;
            if (by_cell.find(c) == by_cell.end()) {
                cells.push_back(c);
                by_cell[c];
            }
            if (!is_empty(samples[k])) {
                by_cell[c].insert(samples[k].radiance);
                all.insert(sample_key(samples[k]));
            }
        }
        const PackedLTrees packed = pack_ltrees(trees);
        std::vector<uint32_t> records;
        std::vector<shared::float4> queries;
        for (uint32_t t = 0; t < trees.size(); ++t) {
            for (uint32_t c : cells) {
                records.push_back(t);
                queries.push_back({static_cast<float>(centre(c & 255u)),
                                   static_cast<float>(centre(c >> 8)), 1e-3f, 0.0f});
            }
        }
        for (uint32_t t = 0; t < trees.size(); ++t) {
            records.push_back(t);
            queries.push_back({0.0f, 0.0f, 2.0f, 0.0f});
        }
        const std::vector<QueryResult> results =
            device_queries(packed, records, queries, static_cast<uint32_t>(total));
        const size_t per_cell = trees.size() * cells.size();
        for (size_t q = per_cell; q < queries.size(); ++q) {
            const uint32_t t = records[q];
            std::multiset<std::tuple<uint32_t, uint32_t, uint32_t>> got;
            for (uint32_t i : results[q].indices) {
                got.insert(sample_key(packed.nodes[packed.trees[t].first_node + i]));
            }
            EXPECT_EQ(results[q].count, all.size())
                << "capacity " << capacities[t] << ", " << inserted << " inserted";
            EXPECT_TRUE(got == all)
                << "capacity " << capacities[t] << ", " << inserted << " inserted: the whole map";
        }
        for (size_t q = 0; q < per_cell; ++q) {
            const uint32_t t = records[q];
            const uint32_t c = cells[q % cells.size()];
            const std::multiset<uint32_t>& want = by_cell[c];
            std::multiset<uint32_t> got;
            for (uint32_t i : results[q].indices) {
                const LTreeNode& n = packed.nodes[packed.trees[t].first_node + i];
                EXPECT_EQ(n.position & 0xffffu, c);
                got.insert(n.radiance);
            }
            EXPECT_EQ(results[q].count, want.size())
                << "capacity " << capacities[t] << ", " << inserted << " inserted, cell ("
                << (c & 255u) << ", " << (c >> 8) << ")";
            EXPECT_EQ(got, want) << "capacity " << capacities[t] << ", " << inserted << " inserted";
            EXPECT_NEAR(results[q].sums.w, static_cast<double>(want.size()), 1e-4);
            ++checked;
        }
    }
    EXPECT_EQ(trees[0].rebuilds, total);
    EXPECT_EQ(trees[3].rebuilds, total / 64);
    EXPECT_GT(checked, 1000u);
}

// ---------------------------------------------------------------------------------------------
// The encodings.

// Random unit directions of the upper hemisphere map into the unit disc, at the direction's
// azimuth and with |(u, v)|^2 = (1 - z) / (1 + z), and unmap back within 1e-5; points of the disc
// unmap to unit directions with z >= 0 and map back. The pole maps to the origin, the equator
// to the unit circle.
TEST(SdrcLTree, ParaboloidMapRoundTrips) {
    std::mt19937 rng(11);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int k = 0; k < 100000; ++k) {
        double d[3] = {normal(rng), normal(rng), normal(rng)};
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (length < 1e-6) {
            continue;
        }
        for (double& c : d) {
            c /= length;
        }
        d[2] = std::abs(d[2]);
        if (d[2] == 0.0) {
            continue;
        }
        const float x = static_cast<float>(d[0]), y = static_cast<float>(d[1]),
                    z = static_cast<float>(d[2]);
        float u, v;
        shared::rc_paraboloid_map(x, y, z, &u, &v);
        const double radius2 = static_cast<double>(u) * u + static_cast<double>(v) * v;
        ASSERT_LE(radius2, 1.0 + 1e-6) << x << " " << y << " " << z;
        if (d[2] > 1e-3) {
            ASSERT_LT(radius2, 1.0);
        }
        ASSERT_NEAR(radius2, (1.0 - z) / (1.0 + z), 1e-6);
        if (radius2 > 1e-8) {
            const double da =
                std::remainder(std::atan2(v, u) - std::atan2(y, x), 2.0 * std::numbers::pi);
            ASSERT_NEAR(da, 0.0, 1e-4);
        }
        float bx, by, bz;
        shared::rc_paraboloid_unmap(u, v, &bx, &by, &bz);
        ASSERT_NEAR(bx, x, 1e-5);
        ASSERT_NEAR(by, y, 1e-5);
        ASSERT_NEAR(bz, z, 1e-5);
    }
    for (int k = 0; k < 100000; ++k) {
        const double r = std::sqrt(uniform(rng)), a = 2.0 * std::numbers::pi * uniform(rng);
        const float u = static_cast<float>(r * std::cos(a)),
                    v = static_cast<float>(r * std::sin(a));
        float x, y, z;
        shared::rc_paraboloid_unmap(u, v, &x, &y, &z);
        ASSERT_NEAR(std::sqrt(double(x) * x + double(y) * y + double(z) * z), 1.0, 1e-6);
        ASSERT_GE(z, -1e-6f);
        float bu, bv;
        shared::rc_paraboloid_map(x, y, z, &bu, &bv);
        ASSERT_NEAR(bu, u, 1e-5);
        ASSERT_NEAR(bv, v, 1e-5);
    }
    float u = 1.0f, v = 1.0f;
    shared::rc_paraboloid_map(0.0f, 0.0f, 1.0f, &u, &v);
    EXPECT_EQ(u, 0.0f);
    EXPECT_EQ(v, 0.0f);
    for (int k = 0; k < 360; ++k) {
        const double a = k * std::numbers::pi / 180.0;
        const float x = static_cast<float>(std::cos(a)), y = static_cast<float>(std::sin(a));
        shared::rc_paraboloid_map(x, y, 0.0f, &u, &v);
        EXPECT_NEAR(std::hypot(u, v), 1.0, 1e-6);
        EXPECT_NEAR(u, x, 1e-7);
        EXPECT_NEAR(v, y, 1e-7);
    }
}

// Colours over 60 decades (channels zero, equal, or many decades below the largest, and
// negative channels, which count as 0) decode within max / 256 of their value per channel; the
// word decodes as its documented format says. Black, below 1e-32, negative and NaN colours
// encode to 0, which decodes to black.
TEST(SdrcLTree, RgbeDecodesWithinAByteOfTheLargestChannel) {
    EXPECT_EQ(sizeof(LTreeNode), 8u);
    EXPECT_EQ(sizeof(SdrcTree), 16u);
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    size_t checked = 0;
    for (int k = 0; k < 200000; ++k) {
        const double magnitude = std::pow(10.0, -30.0 + 60.0 * uniform(rng));
        float c[3];
        for (float& x : c) {
            x = static_cast<float>(magnitude * uniform(rng));
        }
        switch (k % 6) {
            case 1:  // zero channels
                c[rng() % 3] = 0.0f;
                if (uniform(rng) < 0.5) {
                    c[rng() % 3] = 0.0f;
                }
                break;
            case 2:  // equal channels
                c[1] = c[2] = c[0];
                break;
            case 3:  // a channel far below the largest
                c[rng() % 3] = static_cast<float>(magnitude * std::pow(10.0, -20.0 * uniform(rng)));
                break;
            case 4:  // a negative channel
                c[rng() % 3] = -static_cast<float>(magnitude * uniform(rng));
                break;
            case 5:  // exactly a power of two, and just below one
                c[0] = static_cast<float>(std::ldexp(1.0, static_cast<int>(std::log2(magnitude))));
                c[1] = std::nextafter(c[0], 0.0f);
                break;
            default:
                break;
        }
        const float m = std::max({c[0], c[1], c[2]});
        if (!(m >= 1e-32f)) {
            continue;
        }
        const uint32_t word = shared::rc_rgbe_encode(c[0], c[1], c[2]);
        ASSERT_NE(word, 0u) << c[0] << " " << c[1] << " " << c[2];
        float d[3];
        shared::rc_rgbe_decode(word, &d[0], &d[1], &d[2]);
        const std::array<double, 3> formula = decode_rgbe(word);
        for (int i = 0; i < 3; ++i) {
            ASSERT_EQ(static_cast<double>(d[i]), formula[i]) << std::hex << word;
            const double value = std::max(c[i], 0.0f);
            ASSERT_LE(std::abs(d[i] - value), m / 256.0 * (1.0 + 1e-6))
                << "channel " << i << " of (" << c[0] << ", " << c[1] << ", " << c[2]
                << "): " << d[i];
        }
        ++checked;
    }
    EXPECT_GT(checked, 190000u);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float black[][3] = {{0.0f, 0.0f, 0.0f},     {9e-33f, 5e-33f, 0.0f}, {-1.0f, -2.0f, -3.0f},
                              {nan, nan, nan},        {-1.0f, nan, 0.0f},     {-0.0f, -0.0f, -0.0f},
                              {-1e30f, -1e-30f, 0.0f}};
    for (const auto& c : black) {
        const uint32_t word = shared::rc_rgbe_encode(c[0], c[1], c[2]);
        EXPECT_EQ(word, 0u) << c[0] << " " << c[1] << " " << c[2];
        float r = 1.0f, g = 1.0f, b = 1.0f;
        shared::rc_rgbe_decode(word, &r, &g, &b);
        EXPECT_EQ(r, 0.0f);
        EXPECT_EQ(g, 0.0f);
        EXPECT_EQ(b, 0.0f);
    }
    // The largest colours are capped, not wrapped: finite, and within a byte of the cap.
    const float inf = std::numeric_limits<float>::infinity();
    for (float big : {1e38f, 1.7e38f, std::numeric_limits<float>::max(), inf}) {
        float r, g, b;
        shared::rc_rgbe_decode(shared::rc_rgbe_encode(big, 0.0f, big), &r, &g, &b);
        EXPECT_TRUE(std::isfinite(r) && std::isfinite(b)) << big;
        EXPECT_GE(r, std::min(big, 1.7e38f) * (1.0f - 1.0f / 128.0f)) << big;
        EXPECT_EQ(r, b);
        EXPECT_LT(g, r / 256.0f);
    }
}

}  // namespace
}  // namespace rc
