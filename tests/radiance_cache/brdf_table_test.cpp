// Radiance caching's BRDF tables (host/methods/radiance_cache/brdf_tables.h,
// kernels/radiance_cache/rc_brdf_table.h): the dot product of a radiance's coefficients with a
// table's lookup equals the direct integral of f cos L (host quadrature of the material's own
// BRDF evaluation), the adaptive order grows with the Phong exponent, the glossy-box scene's
// materials are classified (and the classification printed), bad options are refused, the
// build is deterministic, and tables are built once per context and materials.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "material_probes.h"
#include "methods/radiance_cache/brdf_tables.h"
#include "methods/radiance_cache/gauss_legendre.h"
#include "scene/scene_loader.h"
#include "sh_quadrature.h"
#include "shared/spherical_harmonics.h"
#include "test_support.h"
#include "util/error.h"

namespace rc {
namespace {

constexpr int kOrder = RC_SH_MAX_ORDER;
constexpr int kCount = kOrder * kOrder;

Material ward(float alpha_x, float alpha_y) {
    Material m;
    m.name = "ward";
    m.kind = MaterialKind::kWard;
    m.diffuse = glm::vec3(0.0f);
    m.specular = glm::vec3(1.0f);
    m.alpha_x = alpha_x;
    m.alpha_y = alpha_y;
    return m;
}

struct Lookup {
    std::vector<float> coefficients;  // order^2 per direction
    std::vector<int> orders;
};

Lookup lookup(const BrdfTables& tables, size_t material, int order,
              const std::vector<shared::float4>& wo) {
    Context& context = test::shared_context();
    Kernel kernel = context.kernel("radiance_cache/rc_probe.cl", "rc_brdf_lookup_probe");
    const Buffer<shared::float4> directions(context, wo, "wo");
    Buffer<float> out(context, wo.size() * order * order, "lookup");
    Buffer<int> orders(context, wo.size(), "lookup_orders");
    context.launch(kernel, wo.size(), tables.infos()[material], order, tables.coefficients(),
                   tables.orders(), directions, out, orders);
    return {out.download(), orders.download()};
}

// A smooth incoming radiance over the hemisphere.
double radiance(double x, double y, double z) {
    return 1.0 + 0.6 * x - 0.4 * y + 0.8 * z * z + 0.5 * x * z;
}

// The specular lobe f_s(wo, wi) at every direction of `q`, from the material's own evaluation
// (kernels/material_probe.cl; its diffuse part is zero).
std::vector<shared::float4> lobe_values(const Material& material, shared::float4 wo,
                                        const std::vector<shared::float4>& directions) {
    return test::material_values(to_device(material), wo, directions);
}

shared::float4 direction(double theta, double phi) {
    return {static_cast<float>(std::sin(theta) * std::cos(phi)),
            static_cast<float>(std::sin(theta) * std::sin(phi)),
            static_cast<float>(std::cos(theta)), 0.0f};
}

// <c_L, c(wo)> against the direct integral of f_s cos L over the hemisphere (Gauss-Legendre 96 x
// midpoint 192, far finer than the lobes), at random outgoing directions up to 80 degrees.
// Bound: the dot product equals the integral of L P_n F, so it errs by <L - P_n L, F - P_n F>
// plus the bilinear interpolation of the coefficients between texels; 2% of the integral
// (measured: at most 0.7% for these lobes, most of it interpolation) covers both.
TEST(BrdfTable, DotProductMatchesDirectIntegration) {
    const test::DirectionQuadrature fine = test::product_quadrature(0.0, 96, 192);
    const test::DirectionQuadrature coarse = test::product_quadrature(0.0, 32, 64);
    std::vector<double> c_light(kCount, 0.0);
    for (size_t i = 0; i < coarse.weights.size(); ++i) {
        const shared::float4& d = coarse.directions[i];
        float y[kCount];
        shared::rc_sh_eval(d.x, d.y, d.z, kOrder, y);
        for (int k = 0; k < kCount; ++k) {
            c_light[k] += coarse.weights[i] * radiance(d.x, d.y, d.z) * y[k];
        }
    }
    const std::vector<Material> materials = {test::pure_phong(3.0f), test::pure_phong(8.0f),
                                             ward(0.3f, 0.5f)};
    Context& context = test::shared_context();
    // 32 Gauss nodes integrate polynomials of degree 63 in cos(theta_i) exactly: ample for these
    // lobes (F Y is close to a polynomial of degree about 20).
    BrdfTableOptions options;
    options.theta_nodes = 32;
    options.phi_nodes = 64;
    const BrdfTables tables(context, materials, options);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (size_t m = 0; m < materials.size(); ++m) {
        std::vector<shared::float4> wo;
        for (int i = 0; i < 12; ++i) {
            wo.push_back(direction(std::acos(1.0 - uniform(rng) * (1.0 - std::cos(1.4))),
                                   2.0 * std::numbers::pi * uniform(rng)));
        }
        const Lookup looked = lookup(tables, m, kOrder, wo);
        double worst = 0.0;
        for (size_t i = 0; i < wo.size(); ++i) {
            const std::vector<shared::float4> f = lobe_values(materials[m], wo[i], fine.directions);
            double direct = 0.0;
            for (size_t k = 0; k < fine.weights.size(); ++k) {
                const shared::float4& d = fine.directions[k];
                direct += fine.weights[k] * f[k].x * d.z * radiance(d.x, d.y, d.z);
            }
            double dot = 0.0;
            for (int k = 0; k < kCount; ++k) {
                dot += c_light[k] * looked.coefficients[i * kCount + k];
            }
            worst = std::max(worst, std::abs(dot - direct) / direct);
            EXPECT_NEAR(dot, direct, 0.02 * direct) << materials[m].name << " at wo (" << wo[i].x
                                                    << ", " << wo[i].y << ", " << wo[i].z << ")";
        }
        std::printf("%s: largest relative error of the dot product %.5f\n",
                    materials[m].name.c_str(), worst);
    }
}

// At normal incidence (the centre texel of an odd grid) the cosine-weighted Phong lobe is zonal,
// F = (e + 2) / 2pi z^(e+1): c_l^0 = (e + 2) K_l integral over [0, 1] of z^(e+1) P_l(z) (SH,
// K_l = sqrt((2l + 1) / 4pi)) or of z^(e+1) P_l(2z - 1) (HSH, sqrt((2l + 1) / 2pi)), every
// m != 0 coefficient zero, and |F|^2 = ((e + 2) / 2pi)^2 2pi / (2e + 3), so the texel's error at
// order n is sqrt(1 - sum c^2 / |F|^2). Integrals of these polynomials by an exact host
// Gauss-Legendre rule.
TEST(BrdfTable, NormalIncidenceTexelMatchesItsClosedForm) {
    const double e = 12.0;
    BrdfTableOptions options;
    options.resolution = 5;
    const QuadratureRule rule = gauss_legendre(40, 0.0, 1.0);
    for (int basis : {RC_BASIS_SH, RC_BASIS_HSH}) {
        options.basis = basis;
        const BrdfTables tables(test::shared_context(), {test::pure_phong(static_cast<float>(e))},
                                options);
        const int centre = 2 * options.resolution + 2;
        const std::vector<float> c = tables.coefficients().download();
        const double norm2 = (e + 2) * (e + 2) / (2 * std::numbers::pi) / (2 * e + 3);
        double captured = 0.0;
        for (int l = 0; l < kOrder; ++l) {
            double integral = 0.0;
            for (size_t j = 0; j < rule.nodes.size(); ++j) {
                const double z = rule.nodes[j];
                integral += rule.weights[j] * std::pow(z, e + 1) *
                            test::legendre(l, basis == RC_BASIS_SH ? z : 2 * z - 1);
            }
            const double k =
                std::sqrt((2 * l + 1) / ((basis == RC_BASIS_SH ? 4 : 2) * std::numbers::pi));
            const double expected = (e + 2) * k * integral;
            for (int m = -l; m <= l; ++m) {
                const float value = c[centre * kCount + shared::rc_sh_index(l, m)];
                EXPECT_NEAR(value, m == 0 ? expected : 0.0, 2e-5 * (e + 2))
                    << "basis " << basis << " l " << l << " m " << m;
            }
            captured += expected * expected;
            const double error = std::sqrt(std::max(0.0, 1.0 - captured / norm2));
            EXPECT_NEAR(tables.texel_errors()[centre * RC_SH_MAX_ORDER + l], error, 2e-3)
                << "basis " << basis << " order " << l + 1;
        }
    }
}

// Lower or equal order for a sharper lobe, Monte Carlo beyond n_max; and HSH, whose functions
// live on the hemisphere only, needs no more than SH for the same lobe (HSH paper §5).
TEST(BrdfTable, PhongOrderGrowsWithExponent) {
    std::vector<Material> materials;
    const float exponents[] = {1, 4, 8, 16, 32, 128};
    for (float e : exponents) {
        materials.push_back(test::pure_phong(e));
    }
    BrdfTableOptions options;
    options.resolution = 12;
    Context& context = test::shared_context();
    const BrdfTables sh(context, materials, options);
    options.basis = RC_BASIS_HSH;
    const BrdfTables hsh(context, materials, options);
    int previous_order = 0;
    double previous_fallback = 0.0;
    for (size_t i = 0; i < materials.size(); ++i) {
        const BrdfTableSummary& s = sh.summaries()[i];
        std::printf(
            "phong exponent %4.0f: SH %-8s order %2d, Monte Carlo for %5.1f%% | HSH %-8s order "
            "%2d, %5.1f%%\n",
            exponents[i], brdf_kind_name(s.kind), s.order, 100 * s.fallback_fraction,
            brdf_kind_name(hsh.summaries()[i].kind), hsh.summaries()[i].order,
            100 * hsh.summaries()[i].fallback_fraction);
        EXPECT_GE(s.fallback_fraction, previous_fallback) << materials[i].name;
        if (s.kind == RC_BRDF_GLOSSY && s.fallback_fraction == 0.0) {
            EXPECT_GE(s.order, previous_order) << materials[i].name;
            previous_order = s.order;
        }
        previous_fallback = s.fallback_fraction;
        if (s.kind == RC_BRDF_GLOSSY && hsh.summaries()[i].kind == RC_BRDF_GLOSSY &&
            s.fallback_fraction == 0.0) {
            EXPECT_LE(hsh.summaries()[i].order, s.order) << materials[i].name;
        }
    }
    EXPECT_EQ(sh.summaries().front().kind, RC_BRDF_GLOSSY);
    EXPECT_EQ(sh.summaries().front().fallback_fraction, 0.0);
    EXPECT_LT(sh.summaries().front().order, sh.summaries()[3].order);
    EXPECT_EQ(sh.summaries().back().kind, RC_BRDF_FALLBACK);
}

// glossy-box: the diffuse walls need no table; the classification of its glossy materials is
// printed for the record.
TEST(BrdfTable, GlossyBoxMaterialsAreClassified) {
    const Scene scene = load_scene(test::source_dir() / "scenes/glossy-box/scene.json");
    const BrdfTables tables(test::shared_context(), scene.materials);
    ASSERT_EQ(tables.summaries().size(), scene.materials.size());
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const BrdfTableSummary& s = tables.summaries()[i];
        std::printf(
            "glossy-box %-8s %-8s order %2d, Monte Carlo for %5.1f%% of directions, "
            "error at order %d %.3f..%.3f\n",
            s.name.c_str(), brdf_kind_name(s.kind), s.order, 100 * s.fallback_fraction,
            RC_SH_MAX_ORDER, s.min_error_at_max_order, s.max_error_at_max_order);
        if (scene.materials[i].kind == MaterialKind::kDiffuse) {
            EXPECT_EQ(s.kind, RC_BRDF_DIFFUSE) << s.name;
            EXPECT_EQ(tables.infos()[i].first_texel, -1) << s.name;
        } else {
            EXPECT_NE(s.kind, RC_BRDF_DIFFUSE) << s.name;
        }
    }
}

TEST(BrdfTable, RefusesBadOptions) {
    const auto refused = [](void (*change)(BrdfTableOptions&), const std::string& option) {
        BrdfTableOptions options;
        change(options);
        try {
            check_brdf_table_options(options);
            ADD_FAILURE() << option << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
            EXPECT_EQ(e.exit_code(), kExitUsage);
        }
    };
    refused([](BrdfTableOptions& o) { o.resolution = 1; }, "resolution");
    refused([](BrdfTableOptions& o) { o.resolution = 1000; }, "resolution");
    refused([](BrdfTableOptions& o) { o.max_order = 0; }, "max_order");
    refused([](BrdfTableOptions& o) { o.max_order = 11; }, "max_order");
    refused([](BrdfTableOptions& o) { o.max_error = 0.0; }, "max_error");
    refused([](BrdfTableOptions& o) { o.max_error = 1.0; }, "max_error");
    refused([](BrdfTableOptions& o) { o.max_error = std::nan(""); }, "max_error");
    refused([](BrdfTableOptions& o) { o.basis = 2; }, "basis");
    refused([](BrdfTableOptions& o) { o.theta_nodes = 9; }, "theta_nodes");
    refused([](BrdfTableOptions& o) { o.phi_nodes = 19; }, "phi_nodes");
    EXPECT_NO_THROW(check_brdf_table_options({}));
    BrdfTableOptions bad;
    bad.max_order = 0;
    EXPECT_THROW(BrdfTables(test::shared_context(), {test::pure_phong(4.0f)}, bad), Error);
}

// Bitwise the same tables whatever the work-group size.
TEST(BrdfTable, BuildIsDeterministic) {
    const std::vector<Material> materials = {test::pure_phong(8.0f), ward(0.2f, 0.4f)};
    BrdfTableOptions options;
    options.resolution = 8;
    const BrdfTables a(test::shared_context(), materials, options);
    ContextOptions context_options = test::default_context_options();
    context_options.local_size = 1;
    Context other(context_options);
    const BrdfTables b(other, materials, options);
    EXPECT_EQ(a.coefficients().download(), b.coefficients().download());
    EXPECT_EQ(a.texel_orders(), b.texel_orders());
}

// Tables are built once per context and materials: the same materials and options get the same
// tables without a build; another material, other options or another context build their own,
// equal to a fresh build's.
TEST(BrdfTable, SharedTablesAreBuiltOncePerContextAndMaterials) {
    std::vector<Material> materials = {test::pure_phong(8.0f), ward(0.2f, 0.4f)};
    BrdfTableOptions options;
    options.resolution = 8;
    Context context(test::default_context_options());
    bool built = false;
    const auto first = shared_brdf_tables(context, materials, options, &built);
    EXPECT_TRUE(built);
    const auto again = shared_brdf_tables(context, materials, options, &built);
    EXPECT_FALSE(built);
    EXPECT_EQ(first.get(), again.get());
    EXPECT_EQ(first->coefficients().download(),
              BrdfTables(context, materials, options).coefficients().download());

    materials[0] = test::pure_phong(9.0f);
    const auto other_material = shared_brdf_tables(context, materials, options, &built);
    EXPECT_TRUE(built);
    EXPECT_NE(other_material->coefficients().download(), first->coefficients().download());
    options.max_error = 0.05;
    shared_brdf_tables(context, materials, options, &built);
    EXPECT_TRUE(built);
    Context other(test::default_context_options());
    shared_brdf_tables(other, materials, options, &built);
    EXPECT_TRUE(built);
}

}  // namespace
}  // namespace rc
