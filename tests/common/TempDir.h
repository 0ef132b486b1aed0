#pragma once
// A fresh, empty folder under the system temp dir for one test, removed with everything in it
// when the object dies.
#include <string>

namespace lenslab::test {

class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::string& path() const { return path_; }
    // Writes `text` to path()/name (creating folders) and returns the full path.
    std::string write(const std::string& name, const std::string& text) const;

private:
    std::string path_;
};

}  // namespace lenslab::test
