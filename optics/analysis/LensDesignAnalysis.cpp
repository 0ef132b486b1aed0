#include "analysis/LensDesignAnalysis.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <optional>

#include "firstorder/Chromatic.h"
#include "analysis/DiffractionMtf.h"
#include "analysis/GeometricMtf.h"
#include "prescription/NumberText.h"
#include "prescription/OpticsError.h"
#include "prescription/Wavelength.h"

namespace lenslab {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void require(bool ok, const std::string& source, const std::string& problem) {
    if (!ok) throw SettingError(source + ": " + problem);
}

// The d chief ray's point on the image plane; the axis point when there is none.
Point2 chiefImage(const LensSystem& lensD, const FieldAim& aim, double imageZ) {
    const std::optional<Ray> in = aimedRay(lensD, aim, 0, 0);
    if (!in) return {};
    TraceOptions options;
    options.ignoreApertures = true;
    const TraceResult out = traceRay(lensD, *in, TraceDirection::SceneToFilm, options);
    const std::optional<Vec3> p = out.ok() ? pointOnPlane(out.ray, imageZ) : std::nullopt;
    return p ? Point2{p->x, p->y} : Point2{};
}

double interpolate(const std::vector<IlluminationSample>& curve, double radius) {
    for (std::size_t k = 1; k < curve.size(); ++k)
        if (radius <= curve[k].filmRadius) {
            const double t = (radius - curve[k - 1].filmRadius) / (curve[k].filmRadius - curve[k - 1].filmRadius);
            return curve[k - 1].relativeIllumination + t * (curve[k].relativeIllumination - curve[k - 1].relativeIllumination);
        }
    return curve.empty() ? kNaN : curve.back().relativeIllumination;
}

class FieldAnalyser {
public:
    FieldAnalyser(const LensDesignAnalysis& out, const DesignAnalysisInputs& in, const std::vector<LensSystem>& lenses,
                  double exitPupilZ)
        : out_(out), in_(in), lenses_(lenses), exitPupilZ_(exitPupilZ), pupil_(pupilPoints(in.spotPattern, in.spotRings)) {}

    FieldAnalysis analyse(double fieldDegrees) const {
        FieldAnalysis f;
        f.fieldDegrees = fieldDegrees;
        const ObjectField object{fieldDegrees, out_.lens.focus.objectZ};
        if (const std::optional<FieldAim> aimD = aimField(out_.lens.lens, object))
            f.reference = chiefImage(out_.lens.lens, *aimD, out_.imageZ);
        // The wavelengths are independent (the wavefront and its PSF above all): traced side by
        // side, then summed in their order, so the result does not depend on the thread count.
        std::vector<WavelengthTrace> traces(lenses_.size());
        tbb::parallel_for(std::size_t(0), lenses_.size(), [&](std::size_t j) { traces[j] = trace(lenses_[j], object, f.reference); });
        std::vector<std::complex<double>> sagittal(out_.frequencies.size()), tangential(out_.frequencies.size());
        double weightTotal = 0;
        for (std::size_t j = 0; j < lenses_.size(); ++j) {
            WavelengthTrace& t = traces[j];
            f.spots.push_back(std::move(t.spot));
            f.fans.push_back(std::move(t.fan));
            f.rmsWavefrontWaves.push_back(t.rmsWaves);
            if (!t.otf) continue;
            // Each wavelength's OTF is relative to its own chief ray: its offset from the reference
            // (lateral colour) is a phase.
            const double sx = t.chiefImage.x - f.reference.x, sy = t.chiefImage.y - f.reference.y;
            const double weight = out_.weights[j];
            for (std::size_t k = 0; k < out_.frequencies.size(); ++k) {
                const double nu = out_.frequencies[k];
                sagittal[k] += weight * t.otf->sagittal.at(nu) * std::polar(1.0, -kTwoPi * nu * sx);
                tangential[k] += weight * t.otf->tangential.at(nu) * std::polar(1.0, -kTwoPi * nu * sy);
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
    // One wavelength at one field: its spot, fan and wavefront's OTF.
    struct WavelengthTrace {
        SpotDiagram spot;
        RayFan fan;
        double rmsWaves = kNaN;
        std::optional<OpticalTransfer> otf;  // none when the wavefront could not be traced
        Point2 chiefImage;
    };

    WavelengthTrace trace(const LensSystem& lens, const ObjectField& object, Point2 reference) const {
        WavelengthTrace t;
        const std::optional<FieldAim> aim = aimField(lens, object);
        if (!aim) {
            t.spot = {lens.wavelength, {}, {}, 0, 0, int(pupil_.size())};
            t.fan = {lens.wavelength, {}, {}, {}};
            return t;
        }
        t.spot = spotDiagram(lens, *aim, out_.imageZ, reference, pupil_);
        t.fan = rayFan(lens, *aim, out_.imageZ, reference, in_.fanSamples);
        const std::optional<WavefrontMap> w = wavefrontMap(lens, *aim, out_.imageZ, exitPupilZ_, in_.wavefront);
        if (!w) return t;
        t.rmsWaves = w->rmsWaves;
        t.otf = opticalTransfer(pointSpreadFunction(*w, in_.psfPadding));
        t.chiefImage = w->chiefImage;
        return t;
    }

    const LensDesignAnalysis& out_;
    const DesignAnalysisInputs& in_;
    const std::vector<LensSystem>& lenses_;
    double exitPupilZ_;
    std::vector<Point2> pupil_;
};

}  // namespace

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
    require(in.maxFrequency >= 0 && std::isfinite(in.maxFrequency), in.maxFrequencySource,
            "the largest frequency must be a positive number of lp/mm (0: the diffraction cutoff)");
    require(in.frequencies >= 2 && in.frequencies <= 257 && in.fanSamples >= 2 && in.fanSamples <= 257 &&
                in.curveSamples >= 2 && in.curveSamples <= 64,
            "analysis", "2-257 frequencies and fan samples, 2-64 curve samples");
}

LensDesignAnalysis analyzeLensDesign(const LensSystem& lensAsBuilt, const DesignAnalysisInputs& in) {
    checkDesignAnalysisInputs(in);
    LensSettings settings = in.lens;
    settings.wavelength = Setting{kWavelengthD, "the d line"};
    LensDesignAnalysis out;
    out.lens = analyzeLens(lensAsBuilt, settings);
    const LensSystem& lensD = out.lens.lens;
    out.wavelengths = in.wavelengths;
    out.weights = in.weights.empty() ? std::vector<double>(in.wavelengths.size(), 1.0) : in.weights;
    out.imageZ = out.lens.focus.imageZExact;
    out.largestFieldDegrees = largestChiefRayField(lensD);
    const double objectZ = out.lens.focus.objectZ;

    // Frequencies up to the on-axis diffraction cutoff (or as asked); the reference curve from the
    // same on-axis aperture at every wavelength.
    const std::optional<FieldAim> axis = aimField(lensD, {0, objectZ});
    const std::optional<ImageSpaceAperture> na = axis ? imageSpaceAperture(lensD, *axis) : std::nullopt;
    if (!na) throw OpticsError("analysis: no ray of the axial field can be aimed through the stop");
    const double aperture = std::fabs(na->x);
    const double maxFrequency = in.maxFrequency > 0 ? in.maxFrequency : 2 * aperture / (kWavelengthD * 1e-6);
    double weightTotal = 0;
    for (double w : out.weights) weightTotal += w;
    for (int k = 0; k < in.frequencies; ++k) {
        const double nu = maxFrequency * k / (in.frequencies - 1);
        out.frequencies.push_back(nu);
        double limit = 0;
        for (std::size_t j = 0; j < out.wavelengths.size(); ++j)
            limit += out.weights[j] * diffractionLimitedMtf(nu, 2 * aperture / (out.wavelengths[j] * 1e-6));
        out.diffractionLimit.push_back(limit / weightTotal);
    }

    std::vector<LensSystem> lenses;
    for (double nm : out.wavelengths) lenses.push_back(atWavelength(lensD, nm));
    const FieldAnalyser analyser(out, in, lenses, out.lens.pupils.exit.z);
    out.fields.resize(in.fields.size());
    tbb::parallel_for(std::size_t(0), in.fields.size(), [&](std::size_t i) {
        out.fields[i] = analyser.analyse(in.fieldsInDegrees ? in.fields[i] : in.fields[i] * out.largestFieldDegrees);
    });

    for (int k = 0; k < in.curveSamples; ++k) out.curveFieldDegrees.push_back(out.largestFieldDegrees * k / (in.curveSamples - 1));
    for (const LensSystem& lens : lenses) out.fieldCurvature.push_back(fieldCurvature(lens, objectZ, out.imageZ, out.curveFieldDegrees));
    if (out.largestFieldDegrees > 0) {
        out.distortion = distortionCurve(lensD, out.lens.firstOrder, out.largestFieldDegrees, in.curveSamples);
        for (FieldAnalysis& f : out.fields)
            if (f.fieldDegrees > 0) f.distortionPercent = distortionCurve(lensD, out.lens.firstOrder, f.fieldDegrees, 2).back().distortionPercent;
    }

    // Relative illumination out to the largest field's image height, read at each field's.
    const std::optional<FieldAim> edge = aimField(lensD, {out.largestFieldDegrees, objectZ});
    const double edgeHeight = edge ? std::fabs(chiefImage(lensD, *edge, out.imageZ).y) : 0.0;
    if (edgeHeight > 0) {
        RelativeIlluminationOptions options;
        options.filmRadii = in.curveSamples;
        options.grid = 64;
        try {
            out.illumination = relativeIllumination(lensD, out.imageZ, edgeHeight, options);
        } catch (const OpticsError&) {
            // Its film-side probe found no passing ray (an image plane on a cover glass): leave it unknown.
        }
    }
    for (FieldAnalysis& f : out.fields) f.relativeIllumination = interpolate(out.illumination, std::fabs(f.reference.y));

    out.focalShift = chromaticFocalShift(lensD, objectZ, out.wavelengths);
    std::vector<double> spectrum;
    for (double nm = 400; nm <= 700; nm += 10) spectrum.push_back(nm);
    out.focalShiftSpectrum = chromaticFocalShift(lensD, objectZ, spectrum);
    return out;
}

}  // namespace lenslab
