#pragma once
// A child program started without a shell (posix_spawn, the arguments passed as they are) in its
// own process group, its stdout read line by line, its stderr kept in a file.
#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace lenslab {

class ChildProcess {
public:
    // argv[0] is the program path. Throws std::runtime_error when it cannot be started.
    ChildProcess(const std::vector<std::string>& argv, const std::string& stderrPath);
    ~ChildProcess();  // kills the group if it still runs
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    // The next stdout line, waiting at most `wait`; nullopt when none came in time or at the end
    // (then finished() is true).
    std::optional<std::string> readLine(std::chrono::milliseconds wait);
    bool finished() const { return eof_; }
    // Waits for the exit; the exit status, or 128 + signal.
    int wait();
    // SIGTERM to the whole group (mpirun passes it to the ranks), SIGKILL after `grace`.
    void killGroup(std::chrono::milliseconds grace);

private:
    pid_t pid_ = -1;
    int stdout_ = -1;
    bool eof_ = false, reaped_ = false;
    int status_ = 0;
    std::string buffer_;
};

}  // namespace lenslab
