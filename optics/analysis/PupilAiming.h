#pragma once
// Rays of one field aimed at chosen points of the aperture stop ("real ray aiming"). A normalised
// pupil point (px, py) in the unit disk names the ray that crosses the stop surface at (px, py) times
// the stop's radius: so pupil coordinates mean the same on and off axis whatever the pupil
// aberration of the elements in front of the stop, the pupil is filled exactly, and vignetting by
// other rims shows as rays that are blocked. The field lies toward +y in the object: a field angle
// theta tilts the incoming light toward -y, and the image forms toward -y.
//
// Millimetres and degrees; lens space (origin at the front vertex, +z toward the scene).
#include <limits>
#include <optional>

#include "prescription/LensSystem.h"
#include "trace/Vec3.h"

namespace lenslab {

struct ObjectField {
    double fieldDegrees = 0;  // angle of the chief ray to the axis in object space (< 90)
    double objectZ = std::numeric_limits<double>::infinity();  // the object plane; infinity: a distant object
};

// What aiming one field needs, found once per field: rays are labelled by where they cross the aim
// plane (a plane in front of the lens), and the chief ray crosses it at chiefAim.
struct FieldAim {
    ObjectField field;
    double aimZ = 0;
    Vec3 direction;    // every ray's direction, for an object at infinity
    Vec3 objectPoint;  // every ray's origin, for a finite object
    double chiefAimX = 0, chiefAimY = 0;
    double inverseJacobian[2][2] = {};  // d(aim point) / d(stop point) at the chief ray
    double stopRadius = 0;
};

// nullopt when no ray of that field reaches the stop's centre.
std::optional<FieldAim> aimField(const LensSystem& lens, const ObjectField& field);

// A solved aim to start the next one from: rays aimed one after another along a path across the
// stop (a radius, say) converge in a step or two from their neighbour's solution, where the chief
// ray's linearisation may not reach the far side of a strongly aberrated pupil at all.
struct AimGuess {
    bool valid = false;
    double aimX = 0, aimY = 0;          // on the aim plane
    double stopX = 0, stopY = 0;        // where that ray crosses the stop, mm
    double inverseJacobian[2][2] = {};  // d(aim point) / d(stop point) there
};

// The incoming ray through the stop point (px, py) * stopRadius, apertures ignored on the way to
// the stop (trace it to learn whether it passes). nullopt when the aim does not converge: no ray of
// this field reaches that point of the stop. With a guess, starts from it and leaves the solution
// in it.
std::optional<Ray> aimedRay(const LensSystem& lens, const FieldAim& aim, double px, double py, AimGuess* guess = nullptr);

// Where a ray leaving the lens meets the plane z = const (its x, y); nullopt when it runs parallel.
std::optional<Vec3> pointOnPlane(const Ray& ray, double z);

// The half-widths of the bundle in image-space direction cosines, along x (sagittal) and y
// (tangential): half the spread of the rays through the pupil's rim at (+-1, 0) and (0, +-1),
// apertures ignored. Signed: negative when the direction cosine falls as the pupil coordinate rises
// (the usual converging image). On axis at infinity, |value| = 1 / (2 f-number). Nullopt when the
// rim rays cannot be aimed at all.
struct ImageSpaceAperture {
    double x = 0, y = 0;
};
std::optional<ImageSpaceAperture> imageSpaceAperture(const LensSystem& lens, const FieldAim& aim);

}  // namespace lenslab
