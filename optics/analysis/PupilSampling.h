#pragma once
// Points spread evenly by area over the unit disk of normalised pupil coordinates, for spot
// diagrams: hexapolar rings (6k points on ring k, the lens designer's usual pattern) or a square grid.
#include <vector>

namespace lenslab {

struct Point2 {
    double x = 0, y = 0;
};

enum class PupilPattern { Hexapolar, Square };

// Hexapolar: the centre and `rings` rings (1 + 3 rings (rings + 1) points). Square: the points of a
// (2 rings + 1)^2 grid that lie in the disk. Throws std::invalid_argument unless 1 <= rings <= 64.
std::vector<Point2> pupilPoints(PupilPattern pattern, int rings);

}  // namespace lenslab
