#include "materials/HairMaterial.h"

#include <algorithm>
#include <optional>
#include <string>

#include "materials/Bsdf.h"
#include "materials/HairLobe.h"

namespace lenslab {

namespace {


// Where the absorption comes from: pbrt-v4 takes the first given of these, in this order.
enum class AbsorptionFrom { SigmaA, Reflectance, Melanin };

class Hair final : public Material {
public:
    struct Inputs {
        AbsorptionFrom from;
        TexturePtr sigmaA, reflectance, eumelanin, pheomelanin;
        TexturePtr eta, betaM, betaN, alpha;
    };
    explicit Hair(Inputs in) : in_(std::move(in)) {}

    void addLobes(const SurfaceHit& hit, Vec3f scale, Bsdf& b) const override {
        HairParams q;
        q.h = std::clamp(2 * hit.v - 1, -1.0f, 1.0f);
        q.eta = std::max(in_.eta->evaluate(hit).x, 1e-3f);
        // A roughness of 0 makes the lobes deltas the model cannot evaluate; textures are held
        // just inside (0, 1], constants are checked when read.
        q.betaM = std::clamp(in_.betaM->evaluate(hit).x, 1e-3f, 1.0f);
        q.betaN = std::clamp(in_.betaN->evaluate(hit).x, 1e-3f, 1.0f);
        q.alphaDeg = in_.alpha->evaluate(hit).x;
        q.sigmaA = sigmaAAt(hit, q.betaN);
        b.add<HairLobe>(scale, q);
    }
    int maxLobes() const override { return 1; }

private:
    Vec3f sigmaAAt(const SurfaceHit& hit, float betaN) const {
        const auto positive = [](Vec3f c) { return Vec3f{std::max(0.0f, c.x), std::max(0.0f, c.y), std::max(0.0f, c.z)}; };
        switch (in_.from) {
        case AbsorptionFrom::SigmaA: return positive(in_.sigmaA->evaluate(hit));
        case AbsorptionFrom::Reflectance: return hairSigmaAFromReflectance(in_.reflectance->evaluate(hit), betaN);
        case AbsorptionFrom::Melanin: break;
        }
        return hairSigmaAFromMelanin(std::max(0.0f, in_.eumelanin->evaluate(hit).x),
                                     std::max(0.0f, in_.pheomelanin->evaluate(hit).x));
    }

    Inputs in_;
};

}  // namespace

std::shared_ptr<Material> makeHairMaterial(const ParamSet& p, const MaterialContext& c) {
    // Constants are checked here; a texture's values are held in range where it is evaluated.
    const auto number = [&](const std::string& name, float fallback, float lo, float hi, const char* range) {
        for (double v : p.getFloats(name))
            if (!(v >= lo && v <= hi)) p.fail("hair \"" + name + "\" must lie in " + range + ", got " + std::to_string(v));
        return floatTextureParam(p, name, fallback, c.textures);
    };
    const auto warn = [&](const std::string& m) { c.warnings.push_back(describe(p.where()) + ": " + m); };

    Hair::Inputs in;
    const bool hasSigma = p.has("sigma_a");
    const std::string reflectanceName = p.has("reflectance") || !p.has("color") ? "reflectance" : "color";
    const bool hasReflectance = p.has(reflectanceName);
    const bool hasMelanin = p.has("eumelanin") || p.has("pheomelanin");
    in.from = hasSigma ? AbsorptionFrom::SigmaA : hasReflectance ? AbsorptionFrom::Reflectance : AbsorptionFrom::Melanin;
    if (hasSigma && (hasReflectance || hasMelanin))
        warn("hair: \"sigma_a\" is given, so \"reflectance\" and the melanin concentrations are ignored");
    else if (hasReflectance && hasMelanin)
        warn("hair: \"reflectance\" is given, so the melanin concentrations are ignored");
    // Constant colours are checked here (textures are held in range where evaluated).
    const auto constantColour = [&](const std::string& name) -> std::optional<Vec3f> {
        if (!p.has(name)) return std::nullopt;
        const ColorOrTexture ct = p.getColorOrTexture(name, {});
        if (ct.texture) return std::nullopt;
        return ct.color;
    };
    if (const auto s = constantColour("sigma_a"))
        if (!(s->x >= 0 && s->y >= 0 && s->z >= 0)) p.fail("hair \"sigma_a\" must not be negative");
    if (const auto r = constantColour(reflectanceName); r && !hasSigma)
        for (float x : {r->x, r->y, r->z})
            if (!(x > 0 && x <= 1)) p.fail("hair \"" + reflectanceName + "\" must lie in (0, 1]: a black fibre has no finite absorption");
    in.sigmaA = textureParam(p, "sigma_a", {0, 0, 0}, c.textures);
    in.reflectance = textureParam(p, reflectanceName, {0.5f, 0.5f, 0.5f}, c.textures);
    // pbrt-v4's default when nothing is given: brown hair, eumelanin 1.3.
    in.eumelanin = number("eumelanin", hasMelanin ? 0.0f : 1.3f, 0, 1e30f, "[0, inf)");
    in.pheomelanin = number("pheomelanin", 0, 0, 1e30f, "[0, inf)");
    in.eta = number("eta", 1.55f, 1e-3f, 1e30f, "(0, inf)");
    in.betaM = number("beta_m", 0.3f, 1e-3f, 1, "(0, 1]");
    in.betaN = number("beta_n", 0.3f, 1e-3f, 1, "(0, 1]");
    in.alpha = number("alpha", 2, -90, 90, "[-90, 90] degrees");
    return std::make_shared<Hair>(std::move(in));
}

}  // namespace lenslab
