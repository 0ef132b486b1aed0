#pragma once
// The lenslab subcommands. Each takes the arguments after its name and returns the exit status.
#include <string>
#include <vector>

namespace lenslab {

int runLensCommand(const std::vector<std::string>& args);
int runAnalyzeCommand(const std::vector<std::string>& args);
int runDiagramCommand(const std::vector<std::string>& args);
int runServeCommand(const std::vector<std::string>& args);
int runRenderCommand(const std::vector<std::string>& args);
int runReportCommand(const std::vector<std::string>& args);
int runOptimiseCommand(const std::vector<std::string>& args);
int runToleranceCommand(const std::vector<std::string>& args);

}  // namespace lenslab
