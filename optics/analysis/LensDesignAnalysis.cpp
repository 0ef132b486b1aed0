#include "analysis/LensDesignAnalysis.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "analysis/DiffractionMtf.h"
#include "analysis/GeometricMtf.h"
#include "analysis/Obscuration.h"
#include "firstorder/Chromatic.h"
#include "prescription/NumberText.h"
#include "prescription/OpticsError.h"
#include "prescription/Wavelength.h"

namespace lenslab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void require(bool ok, const std::string& source, const std::string& problem) {
    if (!ok) throw SettingError(source + ": " + problem);
}

// The chief ray's point on the image plane (apertures and obscurations ignored: an obscured system
// blocks it by design); nullopt when it cannot be aimed or traced.
std::optional<Point2> chiefImage(const LensSystem& lens, const FieldAim& aim, double imageZ) {
    const std::optional<Ray> in = aimedRay(lens, aim, 0, 0);
    if (!in) return std::nullopt;
    TraceOptions options;
    options.ignoreApertures = true;
    const TraceResult out = traceRay(lens, *in, TraceDirection::SceneToFilm, options);
    const std::optional<Vec3> p = out.ok() ? pointOnPlane(out.ray, imageZ) : std::nullopt;
    if (!p) return std::nullopt;
    return Point2{p->x, p->y};
}

// The curve's value at a film radius; none beyond the radii it was sampled at (a field given in
// degrees past the largest field): the curve says nothing there.
std::optional<double> interpolate(const std::vector<IlluminationSample>& curve, double radius) {
    for (std::size_t k = 1; k < curve.size(); ++k)
        if (radius <= curve[k].filmRadius * (1 + 1e-12)) {
            const double t = (radius - curve[k - 1].filmRadius) / (curve[k].filmRadius - curve[k - 1].filmRadius);
            return curve[k - 1].relativeIllumination + t * (curve[k].relativeIllumination - curve[k - 1].relativeIllumination);
        }
    return std::nullopt;
}

// The rays of one field at every wavelength, traced once; nothing for a wavelength the field cannot be aimed at.
struct FieldRays {
    double fieldDegrees = 0;
    std::vector<std::optional<FieldAim>> aims;  // per wavelength
    std::vector<ImageRays> rays;                // per wavelength
};

// The plane z minimising the sum over fields of each field's weighted mean square distance from its
// centroid. Every ray moves linearly with z (p = a + s dz), so that sum is a quadratic in dz.
double leastSpotZ(const std::vector<FieldRays>& fields, const std::vector<double>& weights, double z0) {
    double linear = 0, quadratic = 0;
    for (const FieldRays& f : fields) {
        double total = 0;
        Point2 meanA, meanS;
        for (std::size_t j = 0; j < f.rays.size(); ++j)
            for (std::size_t i = 0; i < f.rays[j].at.size(); ++i) {
                const double w = weights[j] * f.rays[j].weight[i];
                const Point2 a = f.rays[j].pointOn(i, z0), s = f.rays[j].slope[i];
                meanA.x += w * a.x, meanA.y += w * a.y, meanS.x += w * s.x, meanS.y += w * s.y;
                total += w;
            }
        if (!(total > 0)) continue;
        meanA.x /= total, meanA.y /= total, meanS.x /= total, meanS.y /= total;
        double fieldLinear = 0, fieldQuadratic = 0;
        for (std::size_t j = 0; j < f.rays.size(); ++j)
            for (std::size_t i = 0; i < f.rays[j].at.size(); ++i) {
                const double w = weights[j] * f.rays[j].weight[i];
                const Point2 a = f.rays[j].pointOn(i, z0), s = f.rays[j].slope[i];
                const double ax = a.x - meanA.x, ay = a.y - meanA.y, sx = s.x - meanS.x, sy = s.y - meanS.y;
                fieldLinear += w * (ax * sx + ay * sy);
                fieldQuadratic += w * (sx * sx + sy * sy);
            }
        linear += fieldLinear / total;
        quadratic += fieldQuadratic / total;
    }
    return quadratic > 0 ? z0 - linear / quadratic : z0;
}

class FieldAnalyser {
public:
    FieldAnalyser(const LensDesignAnalysis& out, const DesignAnalysisInputs& in, const std::vector<LensSystem>& lenses,
                  std::size_t primary)
        : out_(out), in_(in), lenses_(lenses), primary_(primary) {}

    // The rays of a field at every wavelength, the sampling settled on plane z.
    FieldRays trace(double fieldDegrees, double z) const {
        FieldRays f;
        f.fieldDegrees = fieldDegrees;
        f.aims.resize(lenses_.size());
        f.rays.resize(lenses_.size());
        const ObjectField object{fieldDegrees, out_.lens.focus.objectZ};
        // Without dispersion every wavelength's lens is the same lens: its rays are traced once.
        const std::size_t distinct = out_.lens.lens.isDispersive() ? lenses_.size() : 1;
        tbb::parallel_for(std::size_t(0), distinct, [&](std::size_t j) {
            f.aims[j] = aimField(lenses_[j], object);
            f.rays[j].wavelength = lenses_[j].wavelength;
            if (f.aims[j])
                f.rays[j] = settledImageRays(lenses_[j], *f.aims[j], z, in_.spotSampling, in_.spotTolerance, in_.spotMaxAzimuths);
        });
        for (std::size_t j = distinct; j < lenses_.size(); ++j) {
            f.aims[j] = f.aims[0];
            f.rays[j] = f.rays[0];
            f.rays[j].wavelength = lenses_[j].wavelength;
        }
        return f;
    }

    FieldAnalysis analyse(const FieldRays& rays) const {
        FieldAnalysis f;
        f.fieldDegrees = rays.fieldDegrees;
        const double z = out_.imageZ;
        const std::optional<FieldAim>& primaryAim = rays.aims[primary_];
        const std::optional<Point2> chief = primaryAim ? chiefImage(lenses_[primary_], *primaryAim, z) : std::nullopt;
        // The polychromatic spot on the image plane fixes the reference point.
        std::vector<Point2> points;
        std::vector<double> weights;
        for (std::size_t j = 0; j < rays.rays.size(); ++j)
            for (std::size_t i = 0; i < rays.rays[j].at.size(); ++i) {
                points.push_back(rays.rays[j].pointOn(i, z));
                weights.push_back(out_.weights[j] * rays.rays[j].weight[i]);
            }
        f.traced = !points.empty();
        if (f.traced) f.chiefImage = chief;
        const bool aboutChief = out_.reference == SpotReference::ChiefRay && chief;
        const SpotStatistics all = spotStatistics(points, weights, aboutChief ? chief : std::nullopt);
        f.reference = aboutChief ? *chief : all.centroid;
        f.polychromatic = all;
        f.polychromatic.centroid = {all.centroid.x - f.reference.x, all.centroid.y - f.reference.y};
        const std::optional<Point2> about = aboutChief ? std::optional<Point2>(Point2{}) : std::nullopt;
        for (const ImageRays& r : rays.rays) f.spots.push_back(spotDiagram(r, z, f.reference, about));

        // The wavelengths are independent (the wavefront and its PSF above all): traced side by
        // side, then summed in their order, so the result does not depend on the thread count.
        std::vector<WavelengthTrace> traces(lenses_.size());
        tbb::parallel_for(std::size_t(0), lenses_.size(), [&](std::size_t j) {
            traces[j] = traceWavelength(lenses_[j], rays.aims[j], chief.value_or(Point2{}));
        });
        std::vector<std::complex<double>> sagittal(out_.frequencies.size()), tangential(out_.frequencies.size());
        double weightTotal = 0;
        for (std::size_t j = 0; j < lenses_.size(); ++j) {
            WavelengthTrace& t = traces[j];
            f.fans.push_back(std::move(t.fan));
            f.rmsWavefrontWaves.push_back(t.rmsWaves);
            if (!t.otf) continue;
            // Each wavelength's OTF is relative to its own chief ray: its offset from the reference
            // (lateral colour, the centroid's offset) is a phase.
            const Point2 offset{t.chiefImage.x - f.reference.x, t.chiefImage.y - f.reference.y};
            const double weight = out_.weights[j];
            for (std::size_t k = 0; k < out_.frequencies.size(); ++k) {
                const double nu = out_.frequencies[k];
                sagittal[k] += weight * shiftedTransfer(*t.otf, MtfDirection::Sagittal, nu, offset);
                tangential[k] += weight * shiftedTransfer(*t.otf, MtfDirection::Tangential, nu, offset);
            }
            weightTotal += weight;
        }
        for (std::size_t k = 0; k < out_.frequencies.size(); ++k) {
            f.diffractionSagittal.push_back(weightTotal > 0 ? std::abs(sagittal[k]) / weightTotal : 0.0);
            f.diffractionTangential.push_back(weightTotal > 0 ? std::abs(tangential[k]) / weightTotal : 0.0);
        }
        f.geometricSagittal = geometricMtf(f.spots, out_.weights, MtfDirection::Sagittal, out_.frequencies);
        f.geometricTangential = geometricMtf(f.spots, out_.weights, MtfDirection::Tangential, out_.frequencies);
        return f;
    }

private:
    // One wavelength at one field: its fan and its wavefront's OTF.
    struct WavelengthTrace {
        RayFan fan;
        double rmsWaves = kNaN;
        std::optional<OpticalTransfer> otf;  // none when the wavefront could not be traced
        Point2 chiefImage;
    };

    // Fans are measured from the primary chief ray, as designers read them.
    WavelengthTrace traceWavelength(const LensSystem& lens, const std::optional<FieldAim>& aim, Point2 chief) const {
        WavelengthTrace t;
        t.fan.wavelength = lens.wavelength;
        if (!aim) return t;
        t.fan = rayFan(lens, *aim, out_.imageZ, chief, in_.fanSamples);
        const std::optional<WavefrontMap> w = wavefrontMap(lens, *aim, out_.imageZ, out_.lens.pupils.exit.z, in_.wavefront);
        if (!w) return t;
        t.rmsWaves = w->rmsWaves;
        t.otf = opticalTransfer(pointSpreadFunction(*w, in_.psfPadding));
        t.chiefImage = w->chiefImage;
        return t;
    }

    const LensDesignAnalysis& out_;
    const DesignAnalysisInputs& in_;
    const std::vector<LensSystem>& lenses_;
    std::size_t primary_;
};

// The analysis's lens settings: the primary wavelength as given, else the prescription's own.
LensSettings primarySettings(const LensSystem& lens, const DesignAnalysisInputs& in) {
    LensSettings settings = in.lens;
    if (!settings.wavelength) settings.wavelength = Setting{lens.primaryWavelength, "the prescription's primary wavelength"};
    return settings;
}

}  // namespace

const char* imagePlaneName(ImagePlane plane) {
    switch (plane) {
        case ImagePlane::Paraxial: return "paraxial";
        case ImagePlane::Film: return "film";
        case ImagePlane::Best: return "best";
    }
    return "film";
}

std::optional<ImagePlane> parseImagePlane(const std::string& name) {
    for (ImagePlane p : {ImagePlane::Paraxial, ImagePlane::Film, ImagePlane::Best})
        if (name == imagePlaneName(p)) return p;
    return std::nullopt;
}

const char* spotReferenceName(SpotReference reference) {
    return reference == SpotReference::ChiefRay ? "chief" : "centroid";
}

std::optional<SpotReference> parseSpotReference(const std::string& name) {
    for (SpotReference r : {SpotReference::Centroid, SpotReference::ChiefRay})
        if (name == spotReferenceName(r)) return r;
    return std::nullopt;
}

void checkDesignAnalysisInputs(const DesignAnalysisInputs& in) {
    const std::string& ws = in.wavelengthsSource;
    require(!in.wavelengths.empty() && in.wavelengths.size() <= std::size_t(kMaxAnalysisWavelengths), ws,
            "give 1 to " + std::to_string(kMaxAnalysisWavelengths) + " wavelengths");
    for (double nm : in.wavelengths) {
        const auto problem = wavelengthProblem(nm);
        require(!problem, ws, problem.value_or(""));
    }
    require(in.weights.empty() || in.weights.size() == in.wavelengths.size(), ws, "one weight per wavelength");
    for (double w : in.weights) require(w > 0 && std::isfinite(w), ws, "weights must be positive");
    const std::string& fs = in.fieldsSource;
    require(!in.fields.empty() && in.fields.size() <= std::size_t(kMaxAnalysisFields), fs,
            "give 1 to " + std::to_string(kMaxAnalysisFields) + " fields");
    for (double f : in.fields) {
        if (in.fieldsInDegrees) require(f >= 0 && f < 90, fs, "field " + formatNumber(f) + " deg lies outside 0-90 degrees");
        else require(f >= 0 && f <= 1, fs, "field " + formatNumber(f) + " lies outside 0-1 (a fraction of the largest field)");
    }
    if (in.largestFieldDegrees)
        require(*in.largestFieldDegrees > 0 && *in.largestFieldDegrees < 90, in.largestFieldSource,
                "the largest field must lie between 0 and 90 degrees");
    require(in.maxFrequency >= 0 && std::isfinite(in.maxFrequency), in.maxFrequencySource,
            "the largest frequency must be a positive number of lp/mm (0: the default)");
    require(in.frequencies >= 2 && in.frequencies <= 257 && in.fanSamples >= 2 && in.fanSamples <= 257 &&
                in.curveSamples >= 2 && in.curveSamples <= 64,
            "analysis", "2-257 frequencies and fan samples, 2-64 curve samples");
}

LensDesignAnalysis analyzeLensDesign(const LensSystem& lensAsBuilt, const DesignAnalysisInputs& in) {
    checkDesignAnalysisInputs(in);
    LensDesignAnalysis out;
    out.lens = analyzeLens(lensAsBuilt, primarySettings(lensAsBuilt, in));
    const LensSystem& lensP = out.lens.lens;
    out.primaryWavelength = lensP.wavelength;
    out.wavelengths = in.wavelengths;
    out.weights = in.weights.empty() ? std::vector<double>(in.wavelengths.size(), 1.0) : in.weights;
    out.imagePlane = in.imagePlane;
    out.reference = in.reference;
    if (in.largestFieldDegrees) {
        out.largestFieldDegrees = in.largestFieldDegrees;
        out.largestFieldSource = in.largestFieldSource;
    } else {
        out.largestFieldDegrees = out.lens.field.largestDegrees;
        out.largestFieldSource = out.lens.field.source;
    }
    const double objectZ = out.lens.focus.objectZ;
    out.planes.paraxialZ = paraxialImageZ(lensP, out.lens.firstOrder, objectZ);
    out.planes.filmZ = out.lens.focus.imageZExact;

    // The fields in degrees; fractions of a largest field the lens does not define leave the axis alone.
    std::vector<double> fieldDegrees;
    for (double f : in.fields) {
        if (in.fieldsInDegrees) fieldDegrees.push_back(f);
        else if (out.largestFieldDegrees) fieldDegrees.push_back(f * *out.largestFieldDegrees);
        else if (f == 0) fieldDegrees.push_back(0);
    }
    if (fieldDegrees.empty()) fieldDegrees.push_back(0);

    // Frequencies up to a camera's useful range (or as asked, or the cutoff when it is lower); the
    // reference curve from the same on-axis aperture at every wavelength.
    const std::optional<FieldAim> axis = aimField(lensP, {0, objectZ});
    const std::optional<ImageSpaceAperture> na = axis ? imageSpaceAperture(lensP, *axis) : std::nullopt;
    if (!na) throw OpticsError("analysis: no ray of the axial field can be aimed through the stop");
    const double aperture = std::fabs(na->x);
    out.obscuration = axialObscuration(lensP, *axis);
    const double cutoff = 2 * aperture / (out.primaryWavelength * 1e-6);
    const double maxFrequency = in.maxFrequency > 0 ? in.maxFrequency : std::min(kDefaultMaxFrequency, cutoff);
    double weightTotal = 0;
    for (double w : out.weights) weightTotal += w;
    for (int k = 0; k < in.frequencies; ++k) {
        const double nu = maxFrequency * k / (in.frequencies - 1);
        out.frequencies.push_back(nu);
        double limit = 0;
        for (std::size_t j = 0; j < out.wavelengths.size(); ++j)
            limit += out.weights[j] * diffractionLimitedMtf(nu, 2 * aperture / (out.wavelengths[j] * 1e-6), out.obscuration);
        out.diffractionLimit.push_back(limit / weightTotal);
    }

    std::vector<LensSystem> lenses;
    for (double nm : out.wavelengths) lenses.push_back(atWavelength(lensP, nm));
    // The primary wavelength's own lens, where it is one of the analysis's wavelengths; else added
    // with no weight to the reference only.
    std::size_t primary = std::find(out.wavelengths.begin(), out.wavelengths.end(), out.primaryWavelength) - out.wavelengths.begin();
    std::vector<double> weights = out.weights;
    if (primary == out.wavelengths.size()) {
        lenses.push_back(lensP);
        weights.push_back(0);
    }
    const FieldAnalyser analyser(out, in, lenses, primary);

    // The rays, traced once and settled on the chosen plane (the best plane is found from rays
    // settled on the film, then settled again where it lies).
    const double firstZ = in.imagePlane == ImagePlane::Paraxial ? out.planes.paraxialZ : out.planes.filmZ;
    std::vector<FieldRays> rays(fieldDegrees.size());
    tbb::parallel_for(std::size_t(0), fieldDegrees.size(), [&](std::size_t i) { rays[i] = analyser.trace(fieldDegrees[i], firstZ); });
    out.planes.bestZ = leastSpotZ(rays, weights, firstZ);
    out.imageZ = in.imagePlane == ImagePlane::Paraxial ? out.planes.paraxialZ
                 : in.imagePlane == ImagePlane::Film   ? out.planes.filmZ
                                                       : out.planes.bestZ;
    if (in.imagePlane == ImagePlane::Best)
        tbb::parallel_for(std::size_t(0), fieldDegrees.size(), [&](std::size_t i) { rays[i] = analyser.trace(fieldDegrees[i], out.imageZ); });

    out.fields.resize(fieldDegrees.size());
    tbb::parallel_for(std::size_t(0), fieldDegrees.size(), [&](std::size_t i) { out.fields[i] = analyser.analyse(rays[i]); });
    if (primary == out.wavelengths.size())
        for (FieldAnalysis& f : out.fields) f.spots.pop_back(), f.fans.pop_back(), f.rmsWavefrontWaves.pop_back();

    const double largest = out.largestFieldDegrees.value_or(0.0);
    for (int k = 0; k < in.curveSamples && largest > 0; ++k) out.curveFieldDegrees.push_back(largest * k / (in.curveSamples - 1));
    if (largest > 0) {
        for (std::size_t j = 0; j < out.wavelengths.size(); ++j)
            out.fieldCurvature.push_back(fieldCurvature(lenses[j], objectZ, out.imageZ, out.curveFieldDegrees));
        out.distortion = distortionCurve(lensP, out.lens.firstOrder, largest, in.curveSamples);
    }
    // Each imaged field's distortion (on the axis its limit, 0).
    for (FieldAnalysis& f : out.fields) {
        if (!f.traced) continue;
        if (f.fieldDegrees == 0) {
            f.distortionPercent = 0.0;
            continue;
        }
        const DistortionSample d = distortionCurve(lensP, out.lens.firstOrder, f.fieldDegrees, 2).back();
        if (d.found) f.distortionPercent = d.distortionPercent;
    }

    // Relative illumination out to the largest field's image height, read at each field's.
    const std::optional<FieldAim> edge = largest > 0 ? aimField(lensP, {largest, objectZ}) : std::nullopt;
    const std::optional<Point2> edgeImage = edge ? chiefImage(lensP, *edge, out.imageZ) : std::nullopt;
    const double edgeHeight = edgeImage ? std::hypot(edgeImage->x, edgeImage->y) : 0.0;
    if (edgeHeight > 0) {
        RelativeIlluminationOptions options;
        options.filmRadii = in.curveSamples;
        options.grid = 64;
        try {
            out.illumination = relativeIllumination(lensP, out.imageZ, edgeHeight, options);
        } catch (const OpticsError&) {
            // Its film-side probe found no passing ray (an image plane on a cover glass): leave it unknown.
        }
    }
    for (FieldAnalysis& f : out.fields)
        if (f.chiefImage) f.relativeIllumination = interpolate(out.illumination, std::hypot(f.chiefImage->x, f.chiefImage->y));

    out.focalShift = chromaticFocalShift(lensP, objectZ, out.wavelengths);
    std::vector<double> spectrum;
    for (double nm = 400; nm <= 700; nm += 10) spectrum.push_back(nm);
    out.focalShiftSpectrum = chromaticFocalShift(lensP, objectZ, spectrum);
    out.seidel = seidelSums(lensP, out.largestFieldDegrees.value_or(0), objectZ);
    return out;
}

}  // namespace lenslab
