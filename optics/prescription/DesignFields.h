#pragma once
// The fields a prescription file lists for its own analysis (Zemax FTYP/XFLN/YFLN/FWGN, Code V
// XAN/YAN, XOB/YOB, XIM/YIM, XRI/YRI with WTF): what the file's designer looked at.
#include <cstdint>
#include <vector>

namespace lenslab {

enum class FieldType : std::uint8_t {
    ObjectAngle,          // degrees in object space
    ObjectHeight,         // mm on the object surface
    ParaxialImageHeight,  // mm on the image surface, paraxial
    RealImageHeight,      // mm on the image surface, real chief ray
};

const char* fieldTypeName(FieldType type);  // "object angle", "object height", "paraxial image height", "real image height"

struct FieldPoint {
    double x = 0, y = 0;  // degrees or mm, as the type says
    double weight = 1;
};

struct DesignFields {
    FieldType type = FieldType::ObjectAngle;
    std::vector<FieldPoint> points;  // empty: the file lists none
};

}  // namespace lenslab
