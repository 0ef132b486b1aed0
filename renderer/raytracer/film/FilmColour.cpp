#include "film/FilmColour.h"

#include <stdexcept>

namespace lenslab {

FilmColour::FilmColour(const FilmSpec& film) : scale_(float(film.scale)) {
    if (!film.cameraSensor.empty()) {
        const CameraSensorCurves* curves = findCameraSensorCurves(film.cameraSensor);
        if (!curves) throw std::logic_error("unknown camera sensor " + film.cameraSensor + " (the parser refuses it)");
        camera_.emplace(*curves, film.whiteBalanceKelvin);
    } else if (film.whiteBalanceKelvin > 0) {
        whiteBalance_ = whiteBalanceMatrix(film.whiteBalanceKelvin);
    }
}

Vec3f FilmColour::operator()(Vec3f v) const {
    v = scale_ * v;
    if (camera_) return camera_->toFilm(v);
    return whiteBalance_ ? applyRgbMatrix(*whiteBalance_, v) : v;
}

}  // namespace lenslab
