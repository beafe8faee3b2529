// Energy conservation (white furnace), the normalised Phong albedo of DESIGN.md, and determinism.
#include <tbb/global_control.h>

#include <regex>

#include "base/random.h"
#include "photon_test_util.h"
#include "renderer/shading/frame_shaders.h"

namespace gonio {
namespace {

double EnergyPerPath(const PhotonTraceResult& r, int component = 0) {
    return r.stats.energyUp[component] / static_cast<double>(r.stats.paths);
}

TEST(WhiteFurnace, DiffusePlaneReturnsAllEnergy) {
    PhotonTraceSettings s;
    s.paths = 50000;
    const auto r = test::TraceRib(test::World("Surface \"matte\" \"Kd\" 1\n" + test::Square(1)), s);
    EXPECT_EQ(r.stats.escapedUp, s.paths);
    EXPECT_NEAR(EnergyPerPath(r), 1.0, 0.005);
    EXPECT_NEAR(r.stats.bounces / double(s.paths), 1.0, 1e-12);
}

TEST(WhiteFurnace, ColouredPlaneReturnsKdTimesCs) {
    PhotonTraceSettings s;
    s.paths = 20000;
    const auto r = test::TraceRib(
        test::World("Color [0.2 0.5 1]\nSurface \"matte\" \"Kd\" 0.8\n" + test::Square(1)), s);
    EXPECT_NEAR(EnergyPerPath(r, 0), 0.16, 1e-5);
    EXPECT_NEAR(EnergyPerPath(r, 1), 0.40, 1e-5);
    EXPECT_NEAR(EnergyPerPath(r, 2), 0.80, 1e-5);
}

// A closed diffuse box open at the top, standing on a wide diffuse ground: every photon is
// reflected until it leaves upwards, so with kd = 1 no energy may be lost.
TEST(WhiteFurnace, DiffuseBoxOpenAtTheTop) {
    const std::string walls =
        "Polygon \"P\" [-0.05 -0.05 0  0.05 -0.05 0  0.05 -0.05 0.1  -0.05 -0.05 0.1]\n"
        "Polygon \"P\" [-0.05 0.05 0  0.05 0.05 0  0.05 0.05 0.1  -0.05 0.05 0.1]\n"
        "Polygon \"P\" [-0.05 -0.05 0  -0.05 0.05 0  -0.05 0.05 0.1  -0.05 -0.05 0.1]\n"
        "Polygon \"P\" [0.05 -0.05 0  0.05 0.05 0  0.05 0.05 0.1  0.05 -0.05 0.1]\n";
    PhotonTraceSettings s;
    s.paths = 100000;
    s.maxDepth = 10000;
    const auto r =
        test::TraceRib(test::World("Surface \"matte\" \"Kd\" 1\n" + test::Square(10) + walls), s);
    EXPECT_GT(r.stats.bounces / double(s.paths), 2.0);  // the box really traps light a while
    EXPECT_NEAR(EnergyPerPath(r), 1.0, 0.005);
    EXPECT_EQ(r.stats.absorbed, 0u);
}

// The periodic grass tile with white blades and ground: the ground covers the whole tile and
// photons leaving through a wall come back through the opposite one, so nothing is lost.
TEST(WhiteFurnace, PeriodicGrassTile) {
    std::string rib = test::ReadRib("grass_periodic.rib");
    rib = std::regex_replace(rib, std::regex("Color \\[[^\\]]*\\]"), "Color [1 1 1]");
    rib = std::regex_replace(rib, std::regex("\"Kd\" [0-9.]+"), "\"Kd\" 1");
    rib = std::regex_replace(rib, std::regex("\"float kd\" [0-9.]+ \"float ks\" [0-9.]+"),
                             "\"float kd\" 1 \"float ks\" 0");
    PhotonTraceSettings s;
    s.paths = 40000;
    s.periodic = true;
    s.area = 0.5f;
    s.maxDepth = 10000;
    const auto r = test::TraceRib(rib, s);
    EXPECT_EQ(r.stats.missed, 0u);
    // Blades meet the ground at their base: a hit within the ray offset of that corner may
    // start its next ray under the ground, once in tens of thousands of paths.
    EXPECT_LE(r.stats.escapedDown, s.paths / 10000);
    EXPECT_GT(r.stats.bounces / double(s.paths), 1.5);
    EXPECT_NEAR(EnergyPerPath(r), 1.0, 0.005);
}

// The albedo of the normalised Phong lobe at incidence θ (DESIGN.md's table): a check of the
// importance sampling weights, including the energy lost below the horizon.
double PhongPlaneAlbedo(double exponent, double thetaDeg) {
    PhotonTraceSettings s;
    s.paths = 100000;
    s.isotropic = true;
    s.thetaMin = static_cast<float>((thetaDeg - 0.25) * kDegree);
    s.thetaMax = static_cast<float>((thetaDeg + 0.25) * kDegree);
    const std::string body = "Surface \"metal\"\nAttribute \"brdflight\" \"float exponent\" " +
                             std::to_string(exponent) + "\n" + test::Square(1);
    return EnergyPerPath(test::TraceRib(test::World(body), s));
}

TEST(MicroBrdf, NormalisedPhongAlbedo) {
    EXPECT_NEAR(PhongPlaneAlbedo(10, 30), 0.8660, 0.006);
    EXPECT_NEAR(PhongPlaneAlbedo(10, 60), 0.5047, 0.005);
    EXPECT_NEAR(PhongPlaneAlbedo(10, 85), 0.1713, 0.004);
    EXPECT_NEAR(PhongPlaneAlbedo(1, 30), 0.8808, 0.006);
    EXPECT_NEAR(PhongPlaneAlbedo(1, 60), 0.6090, 0.005);
    EXPECT_NEAR(PhongPlaneAlbedo(1, 85), 0.3631, 0.004);
}

// The tracer takes f and pdf from Sample, which reuses the drawn cos α for the specular lobe
// instead of evaluating cosⁿα again: it must agree with Evaluate at the drawn direction.
TEST(MicroBrdf, SampledValueIsTheEvaluatedOne) {
    uint64_t state = 11;
    auto next = [&] { return ToUnitFloat(MixBits(state += kSplitMix64Step)); };
    int specularDraws = 0;
    for (const MicroBrdf& brdf : {MicroBrdf{0, 1, 25}, MicroBrdf{0.5f, 0.5f, 10},
                                  MicroBrdf{0.3f, 0.7f, 1}, MicroBrdf{0.2f, 0.8f, 200}}) {
        for (int i = 0; i < 20000; ++i) {
            const V3f n = FromLocal(V3f(0, 0, 1), 1 - next(), 6.2831853f * next());
            const V3f wi = FromLocal(n, 1 - next(), 6.2831853f * next());
            const float u0 = next(), u1 = next(), u2 = next();
            const MicroBrdf::Sampled s = brdf.Sample(n, wi, u0, u1, u2);
            const MicroBrdf::Value exact = brdf.Evaluate(n, wi, s.wo);
            specularDraws += u0 * (brdf.kd + brdf.ks) >= brdf.kd;
            // cosⁿα turns the rounding of cos α into n times its relative error.
            const float peak = brdf.ks * (brdf.exponent + 2) / 6.2831853f;
            ASSERT_NEAR(s.value.specular, exact.specular, 2e-6f * brdf.exponent * peak + 1e-6f);
            ASSERT_NEAR(s.value.pdf, exact.pdf, 2e-6f * brdf.exponent * peak + 1e-6f);
        }
    }
    EXPECT_GT(specularDraws, 50000);
}

// The micro BRDF of a shape whose attributes are `a`, from the shaders that ship with gonio.
MicroBrdf MicroBrdfOf(const Attributes& a, Diagnostics& diagnostics) {
    sl::ShadingSystem shaders(diagnostics);
    shaders.SetSearchPath(std::vector<std::string>{DefaultShaderFolder()});
    auto surface = LoadShaderInstance(shaders, a.surface, sl::ShaderType::Surface, Imath::M44f(),
                                      Declarations(), Options(), diagnostics);
    EXPECT_TRUE(surface);
    return surface ? MicroBrdfFromShader(*surface, a, diagnostics) : MicroBrdf{};
}

TypedParam Float(const char* name, double value) {
    ParamDecl decl;
    decl.name = name;
    return TypedParam{decl, {value}, {}};
}

// kd, ks and the exponent come from the compiled shader's declared defaults (shaders/*.sl),
// then from the RIB's values, then from Attribute "brdflight".
TEST(MicroBrdf, ShaderDefaultsAndOverrides) {
    Diagnostics diagnostics;
    Attributes a;
    a.surface.name = "plastic";
    MicroBrdf m = MicroBrdfOf(a, diagnostics);
    EXPECT_FLOAT_EQ(m.kd, 0.5f);
    EXPECT_FLOAT_EQ(m.ks, 0.5f);
    EXPECT_FLOAT_EQ(m.exponent, 10.0f);
    a.surface.params.push_back(Param{"float roughness", {0.25}, {}, false, {}});
    a.surface.params.push_back(Param{"Kd", {0.7}, {}, false, {}});
    m = MicroBrdfOf(a, diagnostics);
    EXPECT_FLOAT_EQ(m.kd, 0.7f);
    EXPECT_FLOAT_EQ(m.exponent, 4.0f);
    a.user["brdflight"].Set(Float("exponent", 25), {});
    a.user["brdflight"].Set(Float("ks", 0.1), {});
    m = MicroBrdfOf(a, diagnostics);
    EXPECT_FLOAT_EQ(m.exponent, 25.0f);
    EXPECT_FLOAT_EQ(m.ks, 0.1f);
    a = Attributes();
    a.surface.name = "metal";
    m = MicroBrdfOf(a, diagnostics);
    EXPECT_FLOAT_EQ(m.kd, 0.0f);
    EXPECT_FLOAT_EQ(m.ks, 1.0f);
    a.surface.name = "matte";
    m = MicroBrdfOf(a, diagnostics);
    EXPECT_FLOAT_EQ(m.kd, 1.0f);
    EXPECT_FLOAT_EQ(m.ks, 0.0f);
    EXPECT_EQ(diagnostics.WarningCount(), 0);
}

std::vector<float> ModelRows(const char* rib, int threads, uint64_t seed) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    PhotonTraceSettings s;
    s.paths = 20000;
    s.seed = seed;
    return test::TraceRib(test::ReadRib(rib), s).rows;
}

// Triangles (grass) and exact quadrics (brushed metal's cylinders and disks).
TEST(Determinism, SameMapForAnyThreadCount) {
    for (const char* rib : {"grass.rib", "brushed_metal.rib"}) {
        SCOPED_TRACE(rib);
        const std::vector<float> one = ModelRows(rib, 1, 7), two = ModelRows(rib, 2, 7),
                                 four = ModelRows(rib, 4, 7);
        ASSERT_FALSE(one.empty());
        EXPECT_EQ(one, two);
        EXPECT_EQ(one, four);
        EXPECT_NE(one, ModelRows(rib, 2, 8));
    }
}

}  // namespace
}  // namespace gonio
