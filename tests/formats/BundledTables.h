#pragma once
// What the writers' round-trip tests share: a bundled lens as gap-after rows, and the check that a
// written file holds the lines a feature must appear as.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "PrescriptionJson.h"
#include "TextContains.h"
#include "prescription/LensTable.h"

namespace lenslab::test {

inline LensTable bundled(const std::string& name) {
    return withGapAfterRows(readLensTable(std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + name));
}

inline void expectLines(const std::string& written, std::initializer_list<const char*> parts) {
    for (const char* part : parts) EXPECT_TRUE(contains(written, part)) << part << " in\n" << written;
}

}  // namespace lenslab::test
