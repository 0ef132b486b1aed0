#pragma once
// The lens designer's analysis of a lens at one aperture and focus: per field and wavelength the
// spot diagram and ray fans, per field the geometric and diffraction MTF (polychromatic); field
// curvature, distortion, relative illumination against field; chromatic focal shift against
// wavelength. Everything is measured on one image plane: by default the film plane that focuses
// the d line (LensAnalysis), with spot points and fans relative to the d line's chief ray there.
#include <string>
#include <vector>

#include "analysis/ChromaticFocalShift.h"
#include "analysis/Distortion.h"
#include "analysis/FieldCurvature.h"
#include "settings/LensAnalysis.h"
#include "analysis/RayFan.h"
#include "analysis/RelativeIllumination.h"
#include "analysis/SpotDiagram.h"
#include "analysis/WavefrontMap.h"

namespace lenslab {

// Bounds on one request's work (a live editor and the API call this on every change).
constexpr int kMaxAnalysisFields = 16;
constexpr int kMaxAnalysisWavelengths = 16;

struct DesignAnalysisInputs {
    LensSettings lens;  // aperture and focus as every front end gives them (the wavelength is the d line)
    std::vector<double> wavelengths{kWavelengthF, kWavelengthD, kWavelengthC};  // nm
    std::vector<double> weights;      // per wavelength; empty: equal
    std::vector<double> fields{0, 0.7, 1};
    bool fieldsInDegrees = false;     // false: fractions of the largest field whose chief ray passes
    std::string wavelengthsSource = "wavelengths", fieldsSource = "fields", maxFrequencySource = "max frequency";
    double maxFrequency = 0;          // lp/mm; 0: the d line's diffraction cutoff on axis, 1 / (lambda N)
    int frequencies = 33;             // MTF samples from 0 to maxFrequency
    PupilPattern spotPattern = PupilPattern::Hexapolar;
    int spotRings = 10;
    int fanSamples = 33;
    WavefrontOptions wavefront;
    int psfPadding = 2;
    int curveSamples = 16;            // field curvature, distortion and illumination, from 0 to the largest field
};

struct FieldAnalysis {
    double fieldDegrees = 0;
    Point2 reference;                    // the d chief ray on the image plane (lens x, y), mm
    std::vector<SpotDiagram> spots;      // per wavelength
    std::vector<RayFan> fans;            // per wavelength
    std::vector<double> rmsWavefrontWaves;  // per wavelength; NaN where the wavefront could not be traced
    // Polychromatic (weighted) MTF at LensDesignAnalysis::frequencies.
    std::vector<double> geometricSagittal, geometricTangential, diffractionSagittal, diffractionTangential;
    double distortionPercent = 0;
    double relativeIllumination = 0;     // at the d chief ray's image height
};

struct LensDesignAnalysis {
    LensAnalysis lens;                   // at the d line: first order, stop, focus, colour
    std::vector<double> wavelengths, weights;
    double largestFieldDegrees = 0;
    double imageZ = 0;                   // the image plane, lens z (mm)
    std::vector<double> frequencies;     // lp/mm
    std::vector<double> diffractionLimit;  // aberration-free MTF at the on-axis aperture, weighted over wavelengths
    std::vector<FieldAnalysis> fields;
    std::vector<double> curveFieldDegrees;  // where the curves below are sampled
    std::vector<std::vector<FieldCurvatureSample>> fieldCurvature;  // per wavelength, at curveFieldDegrees
    std::vector<DistortionSample> distortion;                       // at curveFieldDegrees (d line, F' plane)
    std::vector<IlluminationSample> illumination;                   // film radius 0 to the largest field's image
    std::vector<FocalShiftSample> focalShift;          // at each analysis wavelength
    std::vector<FocalShiftSample> focalShiftSpectrum;  // 400 to 700 nm every 10 nm
};

// The inputs' own check (counts, ranges); SettingError naming the input's source. The lens settings
// are analyzeLens's to check.
void checkDesignAnalysisInputs(const DesignAnalysisInputs& inputs);

// Throws SettingError (from either check) or OpticsError when the lens cannot be analysed at all.
LensDesignAnalysis analyzeLensDesign(const LensSystem& lens, const DesignAnalysisInputs& inputs);

}  // namespace lenslab
