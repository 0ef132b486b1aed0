#include "UnwrittenFeatures.h"

#include <optional>

namespace lenslab {

namespace {

std::optional<std::string> unwrittenRowFeature(const LensTableRow& row) {
    if (row.coordinateBreak) return "a coordinate break";
    if (row.frame) return "a decentre or tilt";
    if (!row.form.isEvenAsphere()) return std::string("a surface of the kind ") + surfaceKindName(row.form.kind);
    if (row.clearShape) return std::string("a ") + apertureKindName(row.clearShape->kind) + " or decentred clear aperture";
    if (row.obscurationShape) return "a shaped or decentred obscuration";
    if (row.automaticDiameter) return "a clear aperture the file leaves to the program";
    return std::nullopt;
}

}  // namespace

void refuseUnwrittenFeatures(const LensTable& table, const std::string& format) {
    const std::string tail = ": lenslab does not write it to a " + format + " (keep the prescription's own file)";
    if (table.imageFrame) throw LensTableError(table.name, 0, "a decentred or tilted image surface" + tail);
    if (!table.substitutes.empty())
        throw LensTableError(table.name, 0, "glasses substituted by " + table.substitutes.front().source + tail);
    for (const LensTableRow& row : table.rows)
        if (const auto feature = unwrittenRowFeature(row)) throw LensTableError(table.name, row.line, *feature + tail);
}

}  // namespace lenslab
