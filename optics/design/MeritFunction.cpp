#include "design/MeritFunction.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <memory>
#include <stdexcept>

#include "analysis/DiffractionMtf.h"
#include "analysis/Distortion.h"
#include "analysis/PupilAiming.h"
#include "analysis/SpotDiagram.h"
#include "analysis/WavefrontMap.h"
#include "design/DesignVariable.h"
#include "firstorder/Chromatic.h"
#include "firstorder/FieldOfView.h"
#include "firstorder/FirstOrder.h"
#include "firstorder/Pupils.h"
#include "prescription/NumberText.h"
#include "prescription/OpticsError.h"
#include "prescription/Pi.h"
#include "trace/AxisRay.h"
#include "trace/ExactTrace.h"

namespace lenslab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Why a lens is not one a designer could build; caught by evaluateMerit and reported.
class InvalidLens : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

std::string degrees(double v) { return formatNumber(v) + " deg"; }

// The table's row of each surface (coordinate breaks have none).
std::vector<int> surfaceRows(const LensTable& table) {
    std::vector<int> rows;
    for (int i = 0; i < int(table.rows.size()); ++i)
        if (!table.rows[i].coordinateBreak) rows.push_back(i);
    return rows;
}

}  // namespace

// Everything the operands of an evaluation share, computed once: the lens, its first order and the
// image plane it was traced to, the lens at each wavelength, and the rays of every (field, wavelength)
// a spot needs. Another image plane is a straight move of the same rays (MeritView).
class TracedLens {
public:
    TracedLens(const LensTable& table, const MeritFunction& merit) : merit_(merit) {
        // Measured along the lens's axis ray, as the analysis measures it: a decentred or tilted lens
        // (an as-built one) has its first order and image about that ray, not about the table's z axis.
        lens_ = alongAxisRay(buildLensSystem(table));
        fo_ = computeFirstOrder(lens_);
        objectZ_ = lens_.frontZ() + lens_.objectDistance;
        const std::optional<double> distance = merit.imagePlane == MeritImagePlane::Table ? imageDistance(table) : std::nullopt;
        imageZ_ = distance ? lens_.rearZ() - *distance : paraxialImageZ(lens_, fo_, objectZ_);
        if (!std::isfinite(imageZ_)) throw InvalidLens("the lens forms no finite image");
        weights_ = merit.weights.empty() ? std::vector<double>(merit.wavelengths.size(), 1.0) : merit.weights;
        for (double w : merit.wavelengths) addWavelength(w);
        for (const MeritOperand& op : merit.operands)
            if (op.kind == OperandKind::LateralColour) addWavelength(kWavelengthF), addWavelength(kWavelengthC);
        const int rows = static_cast<int>(table.rows.size());
        const std::vector<int> surfaceRow = surfaceRows(table);
        surfaceOfRow_.assign(rows, -1);
        for (int k = 0; k < int(surfaceRow.size()); ++k) surfaceOfRow_[surfaceRow[k]] = k;
    }

    const LensSystem& lens() const { return lens_; }
    const FirstOrder& firstOrder() const { return fo_; }
    double imageZ() const { return imageZ_; }
    double objectZ() const { return objectZ_; }
    const std::vector<double>& weights() const { return weights_; }
    int surfaceOfRow(int row) const { return row >= 0 && row < int(surfaceOfRow_.size()) ? surfaceOfRow_[row] : -1; }

    // Every wavelength the operands ask for is made at construction: a traced lens is then read only,
    // by the evaluations of every image plane at once.
    const LensSystem& lensAt(double wavelength) const { return lenses_.at(wavelength); }

    // Aims and traces every (field, wavelength) the operands need, side by side.
    void traceFields(const std::vector<std::pair<double, double>>& needed) {
        std::vector<std::pair<double, double>> keys;
        for (const auto& key : needed) {
            addWavelength(key.second);
            if (rays_.emplace(key, FieldRays{}).second) keys.push_back(key);
        }
        tbb::parallel_for(std::size_t(0), keys.size(), [&](std::size_t i) {
            const auto& [field, wavelength] = keys[i];
            FieldRays& f = rays_.at(keys[i]);
            const LensSystem& lens = lenses_.at(wavelength);
            f.aim = aimField(lens, {field, objectZ_});
            if (!f.aim) return;
            const int maxAzimuths = merit_.settle ? merit_.maxAzimuths : merit_.sampling.azimuths;
            f.rays = settledImageRays(lens, *f.aim, imageZ_, merit_.sampling, merit_.samplingTolerance, maxAzimuths);
        });
    }

    struct FieldRays {
        std::optional<FieldAim> aim;
        ImageRays rays;
    };

    const FieldRays& fieldRays(double field, double wavelength) const {
        const FieldRays& f = rays_.at({field, wavelength});
        if (!f.aim || f.rays.at.empty())
            throw InvalidLens("no ray of the " + degrees(field) + " field at " + formatNumber(wavelength) + " nm reaches the image");
        return f;
    }

    // The on-axis field's aim at a wavelength: the spots' own where they traced it.
    std::optional<FieldAim> axialAim(double wavelength) const {
        const auto it = rays_.find({0.0, wavelength});
        if (it != rays_.end() && it->second.aim) return it->second.aim;
        return aimField(lensAt(wavelength), {0, objectZ_});
    }

    PupilQuadrature finestSampling() const {
        PupilQuadrature finest = merit_.sampling;
        for (const auto& [key, f] : rays_)
            if (f.rays.sampling.azimuths > finest.azimuths) finest = f.rays.sampling;
        return finest;
    }

    // The wavelengths an operand is taken over, with their weights.
    std::vector<std::pair<double, double>> wavelengthsOf(const MeritOperand& op) const {
        if (op.wavelength > 0) return {{op.wavelength, 1.0}};
        std::vector<std::pair<double, double>> out;
        for (std::size_t j = 0; j < merit_.wavelengths.size(); ++j) out.push_back({merit_.wavelengths[j], weights_[j]});
        return out;
    }

private:
    void addWavelength(double wavelength) {
        if (!lenses_.count(wavelength)) lenses_.emplace(wavelength, atWavelength(lens_, wavelength));
    }

    const MeritFunction merit_;  // a copy: a traced lens outlives the evaluation that made it
    LensSystem lens_;
    FirstOrder fo_;
    double objectZ_ = 0, imageZ_ = 0;
    std::vector<double> weights_;
    std::vector<int> surfaceOfRow_;
    std::map<double, LensSystem> lenses_;
    std::map<std::pair<double, double>, FieldRays> rays_;
};

namespace {

// A traced lens measured on one image plane: what every operand reads.
class MeritView {
public:
    MeritView(const TracedLens& traced, double imageZ) : traced_(traced), imageZ_(imageZ) {}

    const LensSystem& lens() const { return traced_.lens(); }
    const FirstOrder& firstOrder() const { return traced_.firstOrder(); }
    double imageZ() const { return imageZ_; }
    double objectZ() const { return traced_.objectZ(); }
    int surfaceOfRow(int row) const { return traced_.surfaceOfRow(row); }
    const LensSystem& lensAt(double wavelength) const { return traced_.lensAt(wavelength); }
    const TracedLens::FieldRays& fieldRays(double field, double wavelength) const { return traced_.fieldRays(field, wavelength); }
    std::vector<std::pair<double, double>> wavelengthsOf(const MeritOperand& op) const { return traced_.wavelengthsOf(op); }

private:
    const TracedLens& traced_;
    double imageZ_;
};

// The gap between surfaces a and b (b follows a) at height h, along the light: negative where they cross.
double clearance(const LensSystem& lens, int a, double h) {
    const Surface& s = lens.surfaces[a];
    const Surface& t = lens.surfaces[a + 1];
    return -lens.zDirectionAfter(a) * ((s.z - sag(s, h)) - (t.z - sag(t, h)));
}

bool facesNext(const LensSystem& lens, int a) {
    const Surface& s = lens.surfaces[a];
    const Surface& t = lens.surfaces[a + 1];
    return !s.isMoved() && !t.isMoved() && !s.clearShape && !t.clearShape;
}

// No two neighbouring surfaces cross inside both clear apertures, and the axial beam's marginal rays
// pass every surface (no total internal reflection, no rim in the way).
void checkValidity(const TracedLens& context, const MeritFunction& merit) {
    const LensSystem& lens = context.lens();
    for (int a = 0; a + 1 < int(lens.surfaces.size()); ++a) {
        if (!facesNext(lens, a)) continue;
        const double h = std::min(lens.surfaces[a].apertureRadius, lens.surfaces[a + 1].apertureRadius);
        const double tolerance = 1e-9 * std::max(1.0, std::fabs(lens.surfaces[a].z));
        const double edge = clearance(lens, a, h), centre = clearance(lens, a, 0);
        if (!(centre >= -tolerance) || !(edge >= -tolerance))
            throw InvalidLens("surfaces " + std::to_string(a + 1) + " and " + std::to_string(a + 2) + " cross (gap " +
                              formatNumber(centre) + " mm on the axis, " + formatNumber(edge) + " mm at height " +
                              formatNumber(h) + " mm)");
    }
    for (double wavelength : merit.wavelengths) {
        const LensSystem& at = context.lensAt(wavelength);
        const std::optional<FieldAim> aim = context.axialAim(wavelength);
        if (!aim) throw InvalidLens("no axial ray reaches the stop at " + formatNumber(wavelength) + " nm");
        // Clear apertures may vignette the axial beam (a table's stop wider than its elements pass):
        // that is the lens as stated, not a fault; the surfaces themselves must pass the ray.
        TraceOptions surfacesOnly;
        surfacesOnly.ignoreApertures = true;
        for (const auto& [px, py] : {std::pair{0.0, 1.0}, std::pair{1.0, 0.0}}) {
            constexpr double kRim = 1 - 1e-6;
            const std::optional<Ray> in = aimedRay(at, *aim, kRim * px, kRim * py);
            const TraceResult out = in ? traceRay(at, *in, TraceDirection::SceneToFilm, surfacesOnly) : TraceResult{};
            if (!in || !out.ok())
                throw InvalidLens("the axial marginal ray at " + formatNumber(wavelength) + " nm does not pass" +
                                  (out.surface >= 0 ? " surface " + std::to_string(out.surface + 1) : std::string()) +
                                  " (total internal reflection, or it misses the surface)");
        }
    }
}

Point2 chiefImage(const LensSystem& lens, const FieldAim& aim, double imageZ, double* angleDegrees = nullptr) {
    const std::optional<Ray> in = aimedRay(lens, aim, 0, 0);
    TraceOptions options;
    options.ignoreApertures = true;
    const TraceResult out = in ? traceRay(lens, *in, TraceDirection::SceneToFilm, options) : TraceResult{};
    const std::optional<Vec3> p = out.ok() ? pointOnPlane(out.ray, imageZ) : std::nullopt;
    if (!p) throw InvalidLens("the chief ray of the " + degrees(aim.field.fieldDegrees) + " field does not reach the image");
    if (angleDegrees) *angleDegrees = std::acos(std::min(1.0, std::fabs(out.ray.direction.z))) * 180 / kPi;
    return {p->x, p->y};
}

double rmsSpot(const MeritView& c, const MeritOperand& op) {
    std::vector<Point2> points;
    std::vector<double> weights;
    for (const auto& [wavelength, weight] : c.wavelengthsOf(op)) {
        const ImageRays& rays = c.fieldRays(op.fieldDegrees, wavelength).rays;
        for (std::size_t i = 0; i < rays.at.size(); ++i) {
            points.push_back(rays.pointOn(i, c.imageZ()));
            weights.push_back(weight * rays.weight[i]);
        }
    }
    return spotStatistics(points, weights).rmsRadius;
}

double exitPupilZ(const LensSystem& lens) { return computePupils(lens).exit.z; }

double rmsWavefront(const MeritView& c, const MeritOperand& op) {
    double sum = 0, total = 0;
    const double pupilZ = exitPupilZ(c.lens());
    for (const auto& [wavelength, weight] : c.wavelengthsOf(op)) {
        const FieldAim& aim = *c.fieldRays(op.fieldDegrees, wavelength).aim;
        const std::optional<WavefrontMap> map = wavefrontMap(c.lensAt(wavelength), aim, c.imageZ(), pupilZ);
        if (!map) throw InvalidLens("the wavefront of the " + degrees(op.fieldDegrees) + " field cannot be traced");
        sum += weight * map->rmsWaves;
        total += weight;
    }
    return sum / total;
}

// The diffraction MTF as the analysis takes it: each wavelength's OTF about the polychromatic
// centroid (its chief ray's offset a phase), summed with the weights.
double mtf(const MeritView& c, const MeritOperand& op) {
    const double pupilZ = exitPupilZ(c.lens());
    std::vector<Point2> points;
    std::vector<double> weights;
    const auto wavelengths = c.wavelengthsOf(op);
    for (const auto& [wavelength, weight] : wavelengths) {
        const ImageRays& rays = c.fieldRays(op.fieldDegrees, wavelength).rays;
        for (std::size_t i = 0; i < rays.at.size(); ++i) {
            points.push_back(rays.pointOn(i, c.imageZ()));
            weights.push_back(weight * rays.weight[i]);
        }
    }
    const Point2 reference = spotStatistics(points, weights).centroid;
    std::complex<double> sum = 0;
    double total = 0;
    for (const auto& [wavelength, weight] : wavelengths) {
        const FieldAim& aim = *c.fieldRays(op.fieldDegrees, wavelength).aim;
        const std::optional<WavefrontMap> map = wavefrontMap(c.lensAt(wavelength), aim, c.imageZ(), pupilZ);
        if (!map) throw InvalidLens("the wavefront of the " + degrees(op.fieldDegrees) + " field cannot be traced");
        const OpticalTransfer otf = opticalTransfer(pointSpreadFunction(*map));
        sum += weight * shiftedTransfer(otf, op.direction, op.frequency,
                                        {map->chiefImage.x - reference.x, map->chiefImage.y - reference.y});
        total += weight;
    }
    return std::abs(sum) / total;
}

double edgeThickness(const MeritView& c, int surface) {
    const LensSystem& lens = c.lens();
    const double h = std::min(lens.surfaces[surface].apertureRadius, lens.surfaces[surface + 1].apertureRadius);
    return clearance(lens, surface, h);
}

// The clear semi-diameter less the highest ray of the merit's fields there (rim rays of each field).
double apertureClearance(const MeritView& c, const MeritFunction& merit, int surface) {
    const LensSystem& lens = c.lensAt(merit.wavelengths.empty() ? c.lens().wavelength : merit.wavelengths.front());
    double highest = 0;
    std::vector<double> fields{0};
    for (const MeritOperand& op : merit.operands)
        if (operandUsesField(op.kind)) fields.push_back(op.fieldDegrees);
    for (double field : fields) {
        const std::optional<FieldAim> aim = aimField(lens, {field, c.objectZ()});
        if (!aim) continue;
        for (const auto& [px, py] : {std::pair{0.0, 1.0}, std::pair{0.0, -1.0}, std::pair{1.0, 0.0}}) {
            const std::optional<Ray> in = aimedRay(lens, *aim, px, py);
            if (!in) continue;
            std::vector<Vec3> path;
            TraceOptions options;
            options.ignoreApertures = true;
            options.path = &path;
            traceRay(lens, *in, TraceDirection::SceneToFilm, options);
            if (int(path.size()) > surface + 1) highest = std::max(highest, std::hypot(path[surface + 1].x, path[surface + 1].y));
        }
    }
    return lens.surfaces[surface].apertureRadius - highest;
}

double operandValue(const MeritView& c, const MeritFunction& merit, const MeritOperand& op) {
    const LensSystem& lens = c.lens();
    const FirstOrder& fo = c.firstOrder();
    const int surface = c.surfaceOfRow(op.row);
    if (operandUsesRow(op.kind) && (surface < 0 || (op.kind != OperandKind::ApertureClearance && surface + 1 >= int(lens.surfaces.size()))))
        throw std::invalid_argument(describeOperand(op) + ": no such surface (or no surface after it)");
    switch (op.kind) {
        case OperandKind::EffectiveFocalLength: return fo.efl;
        case OperandKind::FNumber: return fo.efl / computePupils(lens).entrance.diameter;
        case OperandKind::BackFocalDistance: return fo.backFocalDistance;
        case OperandKind::ImageDistance: return lens.rearZ() - c.imageZ();
        case OperandKind::TotalTrack: return lens.frontZ() - c.imageZ();
        case OperandKind::Magnification:
            return std::isfinite(c.objectZ()) ? -fo.efl / (c.objectZ() - fo.zF) : 0.0;
        case OperandKind::Distortion: {
            const std::vector<DistortionSample> curve = distortionCurve(lens, fo, op.fieldDegrees, 2);
            if (curve.empty() || !curve.back().found)
                throw InvalidLens("no chief ray of the " + degrees(op.fieldDegrees) + " field for the distortion");
            return curve.back().distortionPercent;
        }
        case OperandKind::RmsSpot: return rmsSpot(c, op);
        case OperandKind::RmsWavefront: return rmsWavefront(c, op);
        case OperandKind::Mtf: return mtf(c, op);
        case OperandKind::ChiefRayAngle: {
            double angle = 0;
            chiefImage(lens, *c.fieldRays(op.fieldDegrees, lens.wavelength).aim, c.imageZ(), &angle);
            return angle;
        }
        case OperandKind::CentreThickness: return clearance(lens, surface, 0);
        case OperandKind::EdgeThickness: return edgeThickness(c, surface);
        case OperandKind::ApertureClearance: return apertureClearance(c, merit, surface);
        case OperandKind::AxialColour: return computeChromatic(lens, c.objectZ(), std::nullopt).longitudinalColour;
        case OperandKind::LateralColour: {
            double heights[2];
            int k = 0;
            for (double wavelength : {kWavelengthF, kWavelengthC}) {
                const LensSystem& at = c.lensAt(wavelength);
                const std::optional<FieldAim> aim = aimField(at, {op.fieldDegrees, c.objectZ()});
                if (!aim) throw InvalidLens("no chief ray of the " + degrees(op.fieldDegrees) + " field for the lateral colour");
                heights[k++] = chiefImage(at, *aim, c.imageZ()).y;
            }
            return heights[0] - heights[1];
        }
    }
    return kNaN;
}

// The (field, wavelength) pairs whose rays the operands use.
std::vector<std::pair<double, double>> neededRays(const MeritFunction& merit, double primary) {
    std::vector<std::pair<double, double>> needed;
    const auto add = [&](double field, double wavelength) {
        if (std::find(needed.begin(), needed.end(), std::pair{field, wavelength}) == needed.end()) needed.push_back({field, wavelength});
    };
    for (const MeritOperand& op : merit.operands) {
        if (op.kind == OperandKind::ChiefRayAngle) add(op.fieldDegrees, primary);
        if (op.kind != OperandKind::RmsSpot && op.kind != OperandKind::RmsWavefront && op.kind != OperandKind::Mtf) continue;
        if (op.wavelength > 0) add(op.fieldDegrees, op.wavelength);
        else
            for (double w : merit.wavelengths) add(op.fieldDegrees, w);
    }
    return needed;
}

}  // namespace

double meritValue(const std::vector<double>& residuals) {
    double sum = 0;
    for (double r : residuals) sum += r * r;
    return sum;
}

namespace {

// The operands on one image plane of a traced lens.
MeritEvaluation measure(const std::shared_ptr<const TracedLens>& traced, double imageZ, const MeritFunction& merit) {
    MeritEvaluation out;
    const MeritView view(*traced, imageZ);
    out.values.resize(merit.operands.size());
    for (std::size_t i = 0; i < merit.operands.size(); ++i) {
        const double v = operandValue(view, merit, merit.operands[i]);
        if (!std::isfinite(v)) throw InvalidLens(describeOperand(merit.operands[i]) + " is not a finite number");
        out.values[i] = v;
        out.residuals.push_back(operandResidual(merit.operands[i], v));
    }
    out.sampling = traced->finestSampling();
    out.merit = meritValue(out.residuals);
    out.valid = true;
    out.traced = traced;
    return out;
}

// Runs one evaluation: a lens that is not valid has its reason instead of values.
template <class Evaluate>
MeritEvaluation guarded(Evaluate evaluate) {
    try {
        return evaluate();
    } catch (const InvalidLens& e) {
        MeritEvaluation out;
        out.problem = e.what();
        return out;
    } catch (const OpticsError& e) {
        MeritEvaluation out;
        out.problem = e.what();
        return out;
    } catch (const LensTableError& e) {
        MeritEvaluation out;
        out.problem = e.problem();
        return out;
    }
}

}  // namespace

MeritEvaluation evaluateMerit(const LensTable& table, const MeritFunction& merit, const DesignRules& rules) {
    return guarded([&] {
        const bool ruled = !rules.pickups.empty() || rules.marginalRayImageSolve;
        LensTable applied;
        if (ruled) {
            applied = table;
            applyDesignRules(applied, rules);
        }
        auto traced = std::make_shared<TracedLens>(ruled ? applied : table, merit);
        traced->traceFields(neededRays(merit, traced->lens().wavelength));
        checkValidity(*traced, merit);
        return measure(traced, traced->imageZ(), merit);
    });
}

MeritEvaluation evaluateMeritAtImageDistance(const MeritEvaluation& base, double imageDistance, const MeritFunction& merit) {
    if (!base.valid || !base.traced) return base;
    return guarded([&] { return measure(base.traced, base.traced->lens().rearZ() - imageDistance, merit); });
}

MeritFunction defaultMerit(const LensTable& table) {
    MeritFunction merit;
    if (!table.wavelengths.empty()) {
        merit.wavelengths = table.wavelengths;
        merit.weights = table.wavelengthWeights;
    }
    // A table that states no image distance (pbrt's tables end at gap 0: the film is placed by
    // focusing) is measured at its paraxial focus.
    const std::optional<double> distance = imageDistance(table);
    if (!distance || *distance <= 0) merit.imagePlane = MeritImagePlane::Paraxial;
    const LensSystem lens = buildLensSystem(table);
    const FirstOrder fo = computeFirstOrder(lens);
    std::vector<std::pair<double, double>> fields;  // degrees, weight
    if (table.fields.type == FieldType::ObjectAngle && !table.fields.points.empty()) {
        for (const FieldPoint& p : table.fields.points) fields.push_back({std::hypot(p.x, p.y), p.weight});
    } else {
        // A lens that defines no field (an objective used on its axis) is optimised on its axis.
        const FieldOfView view = lensFieldOfView(lens);
        if (view.largestDegrees) {
            for (double fraction : {0.0, 0.7, 1.0}) fields.push_back({fraction * *view.largestDegrees, 1.0});
        } else {
            fields.push_back({0.0, 1.0});
        }
    }
    for (const auto& [field, weight] : fields) {
        MeritOperand spot;
        spot.kind = OperandKind::RmsSpot;
        spot.fieldDegrees = field;
        spot.weight = weight;
        merit.operands.push_back(spot);
    }
    MeritOperand efl;
    efl.kind = OperandKind::EffectiveFocalLength;
    efl.target = fo.efl;
    merit.operands.push_back(efl);
    const std::vector<int> rows = surfaceRows(table);
    for (int k = 0; k + 1 < int(lens.surfaces.size()); ++k) {
        const Surface& s = lens.surfaces[k];
        if (s.mirror || !facesNext(lens, k)) continue;
        const bool glass = s.indexAfter != 1.0;
        for (OperandKind kind : {OperandKind::CentreThickness, OperandKind::EdgeThickness}) {
            MeritOperand bound;
            bound.kind = kind;
            bound.bound = OperandBound::AtLeast;
            bound.row = rows[k];
            bound.target = glass ? (kind == OperandKind::CentreThickness ? 1.0 : 0.5) : 0.0;
            merit.operands.push_back(bound);
        }
    }
    return merit;
}

}  // namespace lenslab
