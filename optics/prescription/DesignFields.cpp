#include "prescription/DesignFields.h"

namespace lenslab {

const char* fieldTypeName(FieldType type) {
    switch (type) {
        case FieldType::ObjectAngle: return "object angle";
        case FieldType::ObjectHeight: return "object height";
        case FieldType::ParaxialImageHeight: return "paraxial image height";
        case FieldType::RealImageHeight: return "real image height";
    }
    return "unknown";
}

}  // namespace lenslab
