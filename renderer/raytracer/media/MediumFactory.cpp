// MakeNamedMedium's types and their parameters. pbrt-v3's homogeneous and heterogeneous default to
// its coefficients (skim milk's, per mm); pbrt-v4's uniformgrid, cloud and nanovdb default to 1 and 1.
#include <cmath>
#include <optional>

#include "core/MeasuredMedia.h"
#include "media/CloudMedium.h"
#include "media/GridMedium.h"
#include "media/HomogeneousMedium.h"
#include "media/NanoVdbMedium.h"
#include "media/ParticipatingMedium.h"

namespace lenslab {

namespace {

const Vec3f kV3SigmaA{0.0011f, 0.0024f, 0.014f}, kV3SigmaS{2.55f, 3.21f, 3.77f};

bool nonNegative(Vec3f v) { return v.x >= 0 && v.y >= 0 && v.z >= 0; }

HenyeyGreenstein phaseOf(const ParamSet& p) {
    const double g = p.getFloat("g", 0);
    if (!(g > -1 && g < 1)) p.fail("g must lie in (-1, 1)");
    return HenyeyGreenstein(float(g));
}

// sigma_a and sigma_s (or a measured medium's, "preset", per mm) times scale.
void coefficients(const ParamSet& p, Vec3f defaultA, Vec3f defaultS, Vec3f& sigmaA, Vec3f& sigmaS) {
    const float scale = float(p.getFloat("scale", 1));
    if (p.has("preset")) {
        const std::string name = p.getString("preset", "");
        const std::optional<MeasuredMedium> m = measuredMedium(name);
        if (!m) p.fail("no measured medium is named \"" + name + "\" (docs/media.md lists them)");
        defaultA = m->sigmaA;
        defaultS = m->sigmaSPrime;
    }
    sigmaA = scale * p.getRgb("sigma_a", defaultA);
    sigmaS = scale * p.getRgb("sigma_s", defaultS);
    if (!nonNegative(sigmaA) || !nonNegative(sigmaS)) p.fail("sigma_a, sigma_s and scale must not be negative");
}

// The medium's box in its own space, "p0" to "p1".
void boxCorners(const ParamSet& p, Vec3f& p0, Vec3f& p1) {
    p0 = p.getPoint("p0", {0, 0, 0});
    p1 = p.getPoint("p1", {1, 1, 1});
    if (!(p0.x < p1.x && p0.y < p1.y && p0.z < p1.z)) p.fail("p0 must lie below p1 on every axis");
}

// A density grid times the coefficients: pbrt-v3's heterogeneous, pbrt-v4's uniformgrid.
std::shared_ptr<const ParticipatingMedium> makeDensityGrid(const ParamSet& p, const Transform& mediumToWorld, Vec3f defaultA,
                                              Vec3f defaultS) {
    Vec3f sigmaA, sigmaS;
    coefficients(p, defaultA, defaultS, sigmaA, sigmaS);
    DensityGrid grid;
    grid.nx = p.getInt("nx", 1);
    grid.ny = p.getInt("ny", 1);
    grid.nz = p.getInt("nz", 1);
    if (grid.nx < 1 || grid.ny < 1 || grid.nz < 1) p.fail("nx, ny and nz must be positive");
    const std::vector<double> density = p.getFloats("density");
    if (density.size() != std::size_t(grid.nx) * grid.ny * grid.nz)
        p.fail("\"density\" has " + std::to_string(density.size()) + " values, nx * ny * nz = " +
               std::to_string(std::size_t(grid.nx) * grid.ny * grid.nz));
    for (double d : density) {
        if (!(d >= 0)) p.fail("\"density\" values must not be negative");
        if (!(float(d) < INFINITY)) p.fail("\"density\" values must be finite single-precision numbers");
        grid.density.push_back(float(d));
    }
    Vec3f p0, p1;
    boxCorners(p, p0, p1);
    const Transform boxToWorld = mediumToWorld * translate(p0.x, p0.y, p0.z) * scale(p1.x - p0.x, p1.y - p0.y, p1.z - p0.z);
    return std::make_shared<GridMedium>(std::move(grid), sigmaA, sigmaS, boxToWorld, phaseOf(p));
}

std::shared_ptr<const ParticipatingMedium> makeCloud(const ParamSet& p, const Transform& mediumToWorld) {
    Vec3f sigmaA, sigmaS, p0, p1;
    coefficients(p, {1, 1, 1}, {1, 1, 1}, sigmaA, sigmaS);
    boxCorners(p, p0, p1);
    CloudShape shape;
    shape.density = float(p.getFloat("density", shape.density));
    shape.wispiness = float(p.getFloat("wispiness", shape.wispiness));
    shape.frequency = float(p.getFloat("frequency", shape.frequency));
    return std::make_shared<CloudMedium>(shape, sigmaA, sigmaS, p0, p1, mediumToWorld, phaseOf(p));
}

std::optional<NanoVdbGrid> readGrid(const ParamSet& p, const std::string& path, const std::string& gridName) {
    try {
        return readNanoVdbFile(path, gridName);
    } catch (const NanoVdbError& e) {
        p.fail(e.what());
    }
}

// pbrt-v4's nanovdb: the float grid "gridname" ("density") of the file, times sigma_a and sigma_s.
// pbrt-v4 makes the medium emit when the file also has a "temperaturename" grid and Lescale > 0.
std::shared_ptr<const ParticipatingMedium> makeNanoVdb(const ParamSet& p, const Transform& mediumToWorld,
                                                       const PathResolver& resolve, std::vector<std::string>& warnings) {
    const std::string name = p.getString("filename", "");
    if (name.empty()) p.fail("the nanovdb medium needs \"string filename\"");
    const std::string path = resolve(name, p.where());
    const std::string gridName = p.getString("gridname", "density");
    std::optional<NanoVdbGrid> density = readGrid(p, path, gridName);
    if (!density) p.fail(path + ": no grid named \"" + gridName + "\"");
    for (int a = 0; a < 3; ++a)
        if (density->activeMin[a] > density->activeMax[a]) p.fail(path + ": grid \"" + gridName + "\" has no active voxels");
    if (density->smallest < 0)
        warnings.push_back(describe(p.where()) + ": " + path + ": grid \"" + gridName + "\" holds negative values (down to " +
                           std::to_string(density->smallest) + "), read as zero density");
    const double leScale = p.getFloat("Lescale", 1);
    p.getFloat("temperatureoffset", p.getFloat("temperaturecutoff", 0));
    p.getFloat("temperaturescale", 1);
    const std::string temperatureName = p.getString("temperaturename", "temperature");
    if (leScale > 0 && readGrid(p, path, temperatureName))
        p.fail(path + ": grid \"" + temperatureName +
               "\" makes the medium emit (pbrt-v4's blackbody emission), which lenslab does not render; \"float Lescale\" 0 "
               "renders it without");
    Vec3f sigmaA, sigmaS;
    coefficients(p, {1, 1, 1}, {1, 1, 1}, sigmaA, sigmaS);
    return std::make_shared<NanoVdbMedium>(std::move(*density), sigmaA, sigmaS, mediumToWorld, phaseOf(p));
}

}  // namespace

std::shared_ptr<const ParticipatingMedium> makeMedium(const std::string& type, const ParamSet& p, const Transform& mediumToWorld,
                                         const PathResolver& resolve, std::vector<std::string>& warnings) {
    std::shared_ptr<const ParticipatingMedium> m;
    if (type == "homogeneous") {
        Vec3f sigmaA, sigmaS;
        coefficients(p, kV3SigmaA, kV3SigmaS, sigmaA, sigmaS);
        m = std::make_shared<HomogeneousMedium>(sigmaA, sigmaS, phaseOf(p));
    } else if (type == "heterogeneous") {
        m = makeDensityGrid(p, mediumToWorld, kV3SigmaA, kV3SigmaS);
    } else if (type == "uniformgrid") {
        if (p.has("temperature") || p.has("Le"))
            p.fail("emitting media (\"Le\", \"temperature\") are not supported: the picture would lack their light");
        m = makeDensityGrid(p, mediumToWorld, {1, 1, 1}, {1, 1, 1});
    } else if (type == "cloud") {
        m = makeCloud(p, mediumToWorld);
    } else if (type == "nanovdb") {
        m = makeNanoVdb(p, mediumToWorld, resolve, warnings);
    } else {
        p.fail("medium \"" + type + "\" is not supported (homogeneous, heterogeneous, uniformgrid, cloud, nanovdb)");
    }
    if (p.has("Le") && !isBlack(p.getRgb("Le", {})))
        p.fail("emitting media (\"Le\") are not supported: the picture would lack their light");
    p.checkAllUsed(warnings, {"type", "Le", "Lescale"});
    return m;
}

}  // namespace lenslab
