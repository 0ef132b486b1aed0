// pbrt-v3's "bumpmap": a plane displaced by a linear ramp d = a u tilts its shading normal by
// atan(a / |dp/du|) against the ramp, and a diffuse plane under a distant light then shows
// cos(light angle + tilt); a constant displacement changes no normal. On curved surfaces the
// displacement times the normal's turning, d dn/du, joins dp/du: a sphere displaced by d keeps its
// normal with tangents (1 + d / r) as long, and a ramp on a cylinder tilts by d over r + d.
#include <gtest/gtest.h>

#include <cmath>

#include "RadianceProbe.h"
#include "ShapeTestScenes.h"
#include "prescription/Pi.h"

namespace lenslab {
namespace {

using test::trace;

constexpr double kRamp = 0.5;                   // displacement per unit u; u runs 1 per metre along x
const double kTilt = std::atan(kRamp);          // 26.57 degrees, the normal leaning toward -x
constexpr double kLightAngle = 30 * kPi / 180;  // the distant light comes from +x of the zenith

// The plane z = 0 with u = x, v = y; `extra` adds mesh parameters (normals).
std::string plane(const std::string& material, const std::string& extra = "") {
    return material + "\nShape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
                      "\"point P\" [-10 -10 0  10 -10 0  10 10 0  -10 10 0] "
                      "\"float uv\" [-10 -10  10 -10  10 10  -10 10] " + extra + "\n";
}

const std::string kTextures =
    "Texture \"ramp\" \"float\" \"bilerp\" \"float v00\" 0 \"float v01\" 0 \"float v10\" " + std::to_string(kRamp) +
    " \"float v11\" " + std::to_string(kRamp) + "\nTexture \"flat\" \"float\" \"constant\" \"float value\" 0.7\n";

std::string matte(const std::string& bump) {
    return "Material \"matte\" \"rgb Kd\" [1 1 1]" + (bump.empty() ? "" : " \"texture bumpmap\" \"" + bump + "\"");
}

SurfaceHit hitAlong(const std::string& world, Vec3f from, Vec3f direction) {
    test::TempDir dir;
    const auto g = test::geometryOf(dir, kTextures + world);
    Intersection it;
    EXPECT_TRUE(trace(*g, from, direction, it)) << world;
    return it.hit;
}

Vec3f shadingNormalAt(const std::string& world, Vec3f target) {
    return hitAlong(world, target + Vec3f{0, 0, 1}, {0, 0, -1}).ns;
}

TEST(BumpMapping, LinearRampTiltsTheShadingNormal) {
    const Vec3f n = shadingNormalAt(plane(matte("ramp")), {0.2f, 0.3f, 0});
    EXPECT_NEAR(std::acos(n.z), kTilt, 1e-4);
    EXPECT_NEAR(n.x, -std::sin(kTilt), 1e-4);  // the surface rises toward +x: its normal leans to -x
    EXPECT_NEAR(n.y, 0, 1e-5);
    // pbrt-v3 reads "bumpmap" for every material (but mix and none).
    for (const std::string m : {"plastic", "metal", "mirror", "glass", "substrate", "uber", "translucent"}) {
        const Vec3f nm = shadingNormalAt(plane("Material \"" + m + "\" \"texture bumpmap\" \"ramp\""), {0.2f, 0.3f, 0});
        EXPECT_NEAR(std::acos(nm.z), kTilt, 1e-4) << m;
    }
    // On a mesh with shading normals pbrt-v3's tangents run against dp/du and dp/dv (its issues #188
    // and #261), so the same ramp tilts the normal the other way.
    const Vec3f flipped =
        shadingNormalAt(plane(matte("ramp"), "\"normal N\" [0 0 1  0 0 1  0 0 1  0 0 1]"), {0.2f, 0.3f, 0});
    EXPECT_NEAR(flipped.x, std::sin(kTilt), 1e-4);
}

// An instance stretched to twice the width along x halves the slope per metre: dp/du follows the
// instance's transform into the world.
TEST(BumpMapping, InstancedPlaneTiltsByItsWorldSlope) {
    const Vec3f n = shadingNormalAt("ObjectBegin \"p\"\n" + plane(matte("ramp")) + "ObjectEnd\n"
                                    "AttributeBegin\nScale 2 1 1\nObjectInstance \"p\"\nAttributeEnd\n",
                                    {0.2f, 0.3f, 0});
    EXPECT_NEAR(std::acos(n.z), std::atan(kRamp / 2), 1e-4);
}

// (On a mesh whose vertex normals vary, pbrt-v3's d dn/du may tilt even a constant displacement.)
TEST(BumpMapping, ConstantDisplacementChangesNothing) {
    for (const std::string& shape : {plane(matte("")),
                                     plane(matte(""), "\"normal N\" [0 0.1 1  0 0.1 1  0 0.1 1  0 0.1 1]"),
                                    matte("") + "\nTranslate 0 0 -1\nShape \"sphere\" \"float phimax\" 300"}) {
        const std::string bumped = std::string(shape).replace(shape.find(']') + 1, 0, " \"texture bumpmap\" \"flat\"");
        for (Vec3f at : {Vec3f{0.2f, 0.3f, 0}, Vec3f{-0.4f, 0.1f, 0}}) {
            const Vec3f a = shadingNormalAt(shape, at), b = shadingNormalAt(bumped, at);
            EXPECT_NEAR(dot(a, b), 1, 1e-6) << bumped;
        }
    }
}

// The sphere of radius r displaced by d is the sphere of radius r + d: the same normal, and dp/du
// and dp/dv longer by (1 + d / r) = 1.35 for d = 0.7 (the "flat" texture), r = 2.
TEST(BumpMapping, ConstantDisplacementOnASphereLengthensItsTangents) {
    const std::string sphere = "Translate 0 0 -2\nShape \"sphere\" \"float radius\" 2";
    for (Vec3f at : {Vec3f{0.3f, 0.2f, 1}, Vec3f{-0.5f, 0.4f, 1}}) {
        const SurfaceHit plain = hitAlong(matte("") + "\n" + sphere, at, {0, 0, -1});
        const SurfaceHit bumped = hitAlong(matte("flat") + "\n" + sphere, at, {0, 0, -1});
        EXPECT_NEAR(dot(bumped.ns, plain.ng), 1, 1e-6);
        EXPECT_LT(length(bumped.dpdu - 1.35f * plain.dpdu), 1e-5f * length(plain.dpdu));
        EXPECT_LT(length(bumped.dpdv - 1.35f * plain.dpdv), 1e-5f * length(plain.dpdv));
    }
}

// A cylinder of radius r displaced by d(u) = a u has the radius r + d(phi) at phi = 2 pi u, so
// dp'/du = 2 pi (r + d) e_phi + a e_r: the normal leans toward -e_phi by atan(a / (2 pi (r + d))).
// At (0, r, 0), u = 1/4: r = 0.5, d = 0.125 give 7.26 degrees (9.04 without the d dn/du term).
TEST(BumpMapping, RampOnACylinderTiltsByTheDisplacedRadius) {
    const double r = 0.5, d = kRamp / 4, tilt = std::atan(kRamp / (2 * kPi * (r + d)));
    const Vec3f n = hitAlong(matte("ramp") + "\nShape \"cylinder\" \"float radius\" 0.5", {0, 3, 0}, {0, -1, 0}).ns;
    EXPECT_NEAR(std::asin(n.x), tilt, 1e-4);  // e_phi = -x here
    EXPECT_NEAR(n.y, std::cos(tilt), 1e-4);
    EXPECT_NEAR(n.z, 0, 1e-5);
}

// A mix has no bump map of its own, and those of its parts are not applied: a warning says so.
TEST(BumpMapping, MixWarnsThatItsPartsBumpsAreNotApplied) {
    test::TempDir dir;
    const std::string world = kTextures + "MakeNamedMaterial \"a\" \"string type\" \"matte\" \"texture bumpmap\" \"ramp\"\n"
                                          "MakeNamedMaterial \"b\" \"string type\" \"plastic\"\n"
                                          "Material \"mix\" \"string namedmaterial1\" \"a\" \"string namedmaterial2\" \"b\"\n"
                                          "Shape \"sphere\"\n";
    const SceneDescription scene = test::parseWorld(dir, world);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("bump maps of the materials inside a mix are not applied"), std::string::npos)
        << scene.warnings[0];
    EXPECT_EQ(shadingNormalAt(world, {0.2f, 0.3f, 0}).x, shadingNormalAt("Shape \"sphere\"\n", {0.2f, 0.3f, 0}).x);
}

// A white diffuse plane under a distant light of radiance scale L at 30 degrees from the zenith,
// seen from straight above: L cos(30 + tilt) / pi with the ramp, L cos(30) / pi without, both
// through the three integrators and through a rendered pixel.
TEST(BumpMapping, RampChangesTheDiffuseRadianceToTheTiltedCosine) {
    test::TempDir dir;
    const std::string light = "LightSource \"distant\" \"point from\" [" + std::to_string(std::sin(kLightAngle)) +
                              " 0 " + std::to_string(std::cos(kLightAngle)) + "] \"point to\" [0 0 0] \"rgb L\" [2 2 2]\n";
    const double flat = 2 * std::cos(kLightAngle) / kPi, bumped = 2 * std::cos(kLightAngle + kTilt) / kPi;
    const IntegratorType types[] = {IntegratorType::Path, IntegratorType::DirectLighting, IntegratorType::Whitted};
    for (const auto& [bump, expected] : {std::pair<std::string, double>{"", flat}, {"ramp", bumped}}) {
        const std::string world = light + kTextures + plane(matte(bump));
        const std::string probeScene = dir.write("p.pbrt", std::string(test::kProbeHeader) + "WorldBegin\n" + world + "WorldEnd\n");
        for (IntegratorType type : types)
            EXPECT_NEAR(test::RadianceProbe(probeScene, type, 1).mean({0.2f, 0.3f, 1}, {0, 0, -1}, 4), expected, 1e-4)
                << bump;
        const std::string rendered = dir.write("r.pbrt", "LookAt 0 0 1  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 20\n"
                                                         "Integrator \"directlighting\" \"integer maxdepth\" 1\n"
                                                         "PixelFilter \"box\"\nWorldBegin\n" + world + "WorldEnd\n");
        const RenderOutput out = test::render(rendered, 5, 5, 4);
        EXPECT_NEAR(test::lum(out.image, 2, 2), expected, 1e-3) << bump;
    }
}

}  // namespace
}  // namespace lenslab
