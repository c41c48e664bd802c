#pragma once
// The stage a job is in, told to whoever runs it: a job (one call per command of the program)
// names its stages as it enters them, so that a front end can show progress without knowing
// how the job is put together.

#include <functional>
#include <string>

namespace capsubot {

/// Told each stage a job enters ("optimize: 2/5 the fastest robust gait (P2)"), and "" when the
/// job is done. Always called on the thread that called the job. Empty: nobody is told.
using StageCallback = std::function<void(const std::string& stage)>;

/// Tells `callback` the stage (nothing when it is empty).
inline void TellStage(const StageCallback& callback, const std::string& stage) {
  if (callback) callback(stage);
}

}  // namespace capsubot
