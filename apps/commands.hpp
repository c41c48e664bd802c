#pragma once
// The subcommands of `capsubot`, one file each.

#include "capsubot/cli/command.hpp"

namespace capsubot::cli {

Command AddSolveCommand(CLI::App& app);
Command AddSimulateCommand(CLI::App& app);
Command AddOrbitsCommand(CLI::App& app);
Command AddSweepCommand(CLI::App& app);
Command AddOptimizeCommand(CLI::App& app);
Command AddDesignCommand(CLI::App& app);
Command AddAttractorsCommand(CLI::App& app);
Command AddPeriodicCommand(CLI::App& app);
Command AddBasinsCommand(CLI::App& app);
Command AddBifurcationCommand(CLI::App& app);
Command AddMergeCommand(CLI::App& app);
Command AddContinueCommand(CLI::App& app);
/// `capsubot completion bash`: the completion script of every command of `app` (add it last).
Command AddCompletionCommand(CLI::App& app);

}  // namespace capsubot::cli
