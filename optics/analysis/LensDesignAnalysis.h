#pragma once
// The lens designer's analysis of a lens at one aperture and focus: per field and wavelength the
// spot diagram and ray fans, per field the geometric and diffraction MTF (polychromatic); field
// curvature, distortion, relative illumination against field; chromatic focal shift against
// wavelength. Every quantity has one definition (docs/analysis.md): the image plane, the spots'
// reference point, the pupil sampling, the wavelengths' weights and the fields are inputs with
// stated defaults, and every view (command line, API, page, report) computes through this function.
#include <optional>
#include <string>
#include <vector>

#include "analysis/ChromaticFocalShift.h"
#include "analysis/Distortion.h"
#include "analysis/FieldCurvature.h"
#include "analysis/RayFan.h"
#include "analysis/RelativeIllumination.h"
#include "analysis/SeidelSums.h"
#include "analysis/SpotDiagram.h"
#include "analysis/WavefrontMap.h"
#include "settings/LensAnalysis.h"

namespace lenslab {

// Bounds on one request's work (a live editor and the API call this on every change).
constexpr int kMaxAnalysisFields = 16;
constexpr int kMaxAnalysisWavelengths = 16;

// Where the spots, fans, wavefronts and MTF are measured.
enum class ImagePlane {
    Paraxial,  // the paraxial image of the plane of focus at the primary wavelength
    Film,      // the film as the camera focuses it: least RMS spot on axis at the primary wavelength
    Best,      // least RMS spot over the analysed fields and wavelengths (their weights)
};
const char* imagePlaneName(ImagePlane plane);  // "paraxial", "film", "best"
std::optional<ImagePlane> parseImagePlane(const std::string& name);

// The point spot radii are measured from.
enum class SpotReference {
    Centroid,  // each wavelength's spot about its own centroid, the polychromatic spot about the weighted one
    ChiefRay,  // every spot about the primary wavelength's chief ray
};
const char* spotReferenceName(SpotReference reference);  // "centroid", "chief"
std::optional<SpotReference> parseSpotReference(const std::string& name);

struct DesignAnalysisInputs {
    LensSettings lens;  // aperture and focus as every front end gives them; the wavelength is the primary one
    std::vector<double> wavelengths{kWavelengthF, kWavelengthD, kWavelengthC};  // nm
    std::vector<double> weights;      // per wavelength; empty: equal
    std::vector<double> fields{0, 0.7, 1};
    bool fieldsInDegrees = false;     // false: fractions of the largest field
    // The largest field when the caller knows it (a render's film diagonal, as an object angle);
    // none: the lens's own (FieldOfView.h).
    std::optional<double> largestFieldDegrees;
    std::string largestFieldSource;
    ImagePlane imagePlane = ImagePlane::Film;
    SpotReference reference = SpotReference::Centroid;
    std::string wavelengthsSource = "wavelengths", fieldsSource = "fields", maxFrequencySource = "max frequency";
    double maxFrequency = 0;          // lp/mm; 0: kDefaultMaxFrequency, or the diffraction cutoff when lower
    int frequencies = 41;             // MTF samples from 0 to maxFrequency
    PupilQuadrature spotSampling;     // where the spots' sampling starts (doubled until settled)
    double spotTolerance = 0.002;     // the relative change of an RMS radius that counts as settled
    int spotMaxAzimuths = 512;
    int fanSamples = 33;
    WavefrontOptions wavefront;
    int psfPadding = 2;
    int curveSamples = 16;            // field curvature, distortion and illumination, from 0 to the largest field
};

// The MTF's default range: what a camera's sensor resolves, not the diffraction cutoff (1000-1500
// lp/mm for fast lenses), which would squeeze every useful frequency into a sliver of the plot.
constexpr double kDefaultMaxFrequency = 200;

struct FieldAnalysis {
    double fieldDegrees = 0;
    bool traced = false;                 // some ray of the field reaches the image plane; false: "not imaged"
    // The primary chief ray on the image plane (lens x, y), mm; none where the field is not imaged
    // or its chief ray cannot be traced: a field no light reaches has no image height.
    std::optional<Point2> chiefImage;
    Point2 reference;                    // where the spots' points are measured from, mm
    std::vector<SpotDiagram> spots;      // per wavelength
    SpotStatistics polychromatic;        // every wavelength's rays with their weights
    std::vector<RayFan> fans;            // per wavelength
    std::vector<double> rmsWavefrontWaves;  // per wavelength; NaN where the wavefront could not be traced
    // Polychromatic (weighted) MTF at LensDesignAnalysis::frequencies.
    std::vector<double> geometricSagittal, geometricTangential, diffractionSagittal, diffractionTangential;
    // Both none where the field is not imaged, or its chief ray (or the illumination curve) is unknown.
    std::optional<double> distortionPercent;
    std::optional<double> relativeIllumination;  // at the primary chief ray's image height
};

struct ImagePlanes {
    double paraxialZ = 0, filmZ = 0, bestZ = 0;  // lens z (mm)
};

struct LensDesignAnalysis {
    LensAnalysis lens;                   // at the primary wavelength: first order, stop, focus, colour, field of view
    double primaryWavelength = 0;        // nm
    std::vector<double> wavelengths, weights;
    std::optional<double> largestFieldDegrees;
    std::string largestFieldSource;      // where the largest field comes from, or why there is none
    ImagePlane imagePlane = ImagePlane::Film;
    SpotReference reference = SpotReference::Centroid;
    ImagePlanes planes;
    double imageZ = 0;                   // the chosen plane, lens z (mm)
    double obscuration = 0;              // the axial pupil's central obscuration, as a fraction of its radius
    std::vector<double> frequencies;     // lp/mm
    std::vector<double> diffractionLimit;  // aberration-free MTF at the on-axis aperture, weighted over wavelengths
    std::vector<FieldAnalysis> fields;
    std::vector<double> curveFieldDegrees;  // where the curves below are sampled
    std::vector<std::vector<FieldCurvatureSample>> fieldCurvature;  // per wavelength, at curveFieldDegrees
    std::vector<DistortionSample> distortion;                       // at curveFieldDegrees (primary, F' plane)
    std::vector<IlluminationSample> illumination;                   // film radius 0 to the largest field's image
    std::vector<FocalShiftSample> focalShift;          // at each analysis wavelength
    std::vector<FocalShiftSample> focalShiftSpectrum;  // 400 to 700 nm every 10 nm
    // Third-order sums at the largest field (on axis where there is none); none for a lens the
    // paraxial theory does not cover (decentred, mirrors, surface forms beyond the even asphere).
    std::optional<SeidelSums> seidel;
};

// The inputs' own check (counts, ranges); SettingError naming the input's source. The lens settings
// are analyzeLens's to check.
void checkDesignAnalysisInputs(const DesignAnalysisInputs& inputs);

// Throws SettingError (from either check) or OpticsError when the lens cannot be analysed at all.
LensDesignAnalysis analyzeLensDesign(const LensSystem& lens, const DesignAnalysisInputs& inputs);

}  // namespace lenslab
