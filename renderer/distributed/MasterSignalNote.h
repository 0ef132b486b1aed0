#pragma once
// While rank 0 collects tiles: when mpirun stops the job (by default it kills every rank once one
// dies) or the user interrupts it, rank 0 says how far the render got and that no image was
// written, then dies of the same signal.
#include <csignal>

namespace lenslab {

class MasterSignalNote {
public:
    explicit MasterSignalNote(int tilesTotal);
    ~MasterSignalNote();
    MasterSignalNote(const MasterSignalNote&) = delete;
    MasterSignalNote& operator=(const MasterSignalNote&) = delete;
    void setTilesDone(int tilesDone);

private:
    struct sigaction previous_[3];
};

}  // namespace lenslab
