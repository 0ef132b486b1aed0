#pragma once
// What the optics tests share: infinity, the bundled lenses, and the check of a reader's error.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "prescription/LensSystem.h"
#include "prescription/LensTable.h"

namespace lenslab::test {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// The repository's lenses/ folder, with its trailing slash.
inline const std::string kLensesDir = std::string(LENSLAB_SOURCE_DIR) + "/lenses/";

inline LensSystem bundled(const std::string& fileName) { return loadLensSystem(kLensesDir + fileName); }

// `read` (a reader given text, or its input) throws a LensTableError of `file` at `line`, whose
// problem contains `part` and whose message starts "file:line: ".
template <class Read>
void expectReadError(Read read, const std::string& input, const std::string& file, int line, const std::string& part) {
    try {
        read();
        ADD_FAILURE() << "no error for:\n" << input;
    } catch (const LensTableError& e) {
        EXPECT_EQ(e.file(), file);
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_NE(e.problem().find(part), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).rfind(file + ":" + std::to_string(line) + ": ", 0), 0u) << e.what();
    }
}

}  // namespace lenslab::test
