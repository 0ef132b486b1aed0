#pragma once
// Where the film must sit to focus at a given object distance.
#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"
#include "firstorder/Pupils.h"

namespace lenslab {

// The closest focus allowed: the image may lie at most this many focal lengths behind F'
// (magnification kMaxMagnification), beyond which the film extension stops being a camera.
constexpr double kMaxMagnification = 10.0;

struct FocusResult {
    bool infinity = false;
    double objectZ = 0;         // object plane, mm from the front vertex (+z toward the scene)
    double imageZThick = 0;     // film z by the thick-lens formula
    double imageZExact = 0;     // film z where exact rays through the pupil converge best (least RMS spot)
    double difference = 0;      // imageZExact - imageZThick
    int raysUsed = 0;           // exact rays that passed the lens
};

// The nearest object distance (from the front vertex) the lens can focus on.
double closestFocusDistance(const FirstOrder& fo);

// Focuses on an object at `distance` mm in front of the front vertex (infinity allowed). The lens's
// stop opening sets the ray bundle. Throws OpticsError for distances inside the front focal length,
// closer than closestFocusDistance, or where no exact ray passes.
FocusResult focusAt(const LensSystem& lens, const FirstOrder& fo, const Pupils& pupils, double distance);

// The plane the thick lens images onto a film at filmZ: its distance from the front vertex,
// infinity when the film lies at or in front of F' (no real object is in focus).
double thickLensFocusForFilm(const LensSystem& lens, const FirstOrder& fo, double filmZ);

// A film placed directly at filmZ (the later course's filmdistance): both models' film there, the
// plane of focus the thick lens's conjugate. Throws OpticsError unless the film lies behind the
// rear vertex.
FocusResult filmPlacedAt(const LensSystem& lens, const FirstOrder& fo, double filmZ);

}  // namespace lenslab
