#include "settings/LensAnalysis.h"

#include <cmath>
#include <limits>

#include "prescription/OpticsError.h"
#include "prescription/Wavelength.h"
#include "trace/AxisRay.h"

namespace lenslab {

namespace {

// Runs `step`, putting the setting's source in front of the optics' own message.
template <class Step>
auto blame(const std::optional<Setting>& setting, Step step) -> decltype(step()) {
    try {
        return step();
    } catch (const OpticsError& e) {
        if (!setting || setting->source.empty() || dynamic_cast<const SettingError*>(&e)) throw;
        throw SettingError(setting->source + ": " + e.what());
    }
}

void refuseBoth(const std::optional<Setting>& a, const std::optional<Setting>& b, const char* what) {
    if (a && b) throw SettingError(a->source + " and " + b->source + " both set the " + what + ": give one of them");
}

// The lens at the requested wavelength (or as it was built: at its primary wavelength).
LensSystem atRequestedWavelength(const LensSystem& lens, const std::optional<Setting>& wavelength) {
    if (!wavelength) return lens;
    if (const auto problem = wavelengthProblem(wavelength->value)) throw SettingError(wavelength->source + ": " + *problem);
    return atWavelength(lens, wavelength->value);
}

}  // namespace

LensAnalysis analyzeLens(const LensSystem& lensAsBuilt, const LensSettings& s) {
    refuseBoth(s.fstop, s.stopDiameter, "aperture");
    refuseBoth(s.focusDistance, s.filmDistance, "focus");
    // A decentred or tilted lens is measured along its axis ray (trace/AxisRay.h).
    const LensSystem table = alongAxisRay(atRequestedWavelength(lensAsBuilt, s.wavelength));
    LensAnalysis a;
    a.firstOrder = computeFirstOrder(table);
    a.aperture = computeApertureRange(table, a.firstOrder);
    a.fstop = s.stopDiameter ? blame(s.stopDiameter, [&] {
        return fstopForStopDiameter(table, a.firstOrder, a.aperture, s.stopDiameter->value);
    })
                             : s.fstop ? s.fstop->value : a.aperture.fstopMin;
    a.stopDiameter = blame(s.fstop, [&] { return stopDiameterForFstop(table, a.firstOrder, a.aperture, a.fstop); });
    a.lens = withStopDiameter(table, a.stopDiameter);
    a.pupils = computePupils(a.lens);
    a.thick = makeThickLens(a.firstOrder, a.pupils);
    if (s.filmDistance) {
        a.focus = blame(s.filmDistance, [&] { return filmPlacedAt(a.lens, a.firstOrder, table.rearZ() - s.filmDistance->value); });
    } else if (s.focusDistance && s.focusFromFilm) {
        // The object's distance from the film is given: the film position depends on the focus, so
        // iterate (the film moves by far less than the distance).
        double filmZ = a.firstOrder.zFPrime;
        for (int it = 0; it < 8; ++it) {
            const double fromVertex = s.focusDistance->value + filmZ - table.frontZ();
            a.focus = blame(s.focusDistance, [&] { return focusAt(a.lens, a.firstOrder, a.pupils, fromVertex); });
            const double next = s.focusModel == FocusModel::Thick ? a.focus.imageZThick : a.focus.imageZExact;
            if (std::fabs(next - filmZ) < 1e-9) break;
            filmZ = next;
        }
    } else {
        const double distance = s.focusDistance ? s.focusDistance->value : std::numeric_limits<double>::infinity();
        a.focus = blame(s.focusDistance, [&] { return focusAt(a.lens, a.firstOrder, a.pupils, distance); });
    }
    a.field = lensFieldOfView(lensAsBuilt);
    a.chromatic = computeChromatic(a.lens, a.focus.infinity ? std::numeric_limits<double>::infinity() : a.focus.objectZ,
                                   a.field.largestDegrees);
    return a;
}

LensAnalysis describeLens(const LensSystem& lens, const LensSettings& settings) {
    try {
        return analyzeLens(lens, settings);
    } catch (const SettingError&) {
        throw;
    } catch (const AfocalError&) {
        LensAnalysis a;
        a.lens = alongAxisRay(atRequestedWavelength(lens, settings.wavelength));
        a.afocal = true;
        return a;
    } catch (const OpticsError& e) {
        LensAnalysis a;
        a.lens = alongAxisRay(atRequestedWavelength(lens, settings.wavelength));
        a.firstOrder = computeFirstOrder(a.lens);
        a.incomplete = e.what();
        return a;
    }
}

LensAnalysis analyzeLens(const LensSystem& lens, std::optional<double> fstop, double focusDistance) {
    LensSettings s;
    if (fstop) s.fstop = Setting{*fstop, ""};
    s.focusDistance = Setting{focusDistance, ""};
    return analyzeLens(lens, s);
}

}  // namespace lenslab
