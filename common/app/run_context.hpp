#pragma once
// The GL context of a run: a window when there is a display and the run wants one, headless (EGL)
// otherwise, and headless after all when the window cannot be made.
#include <memory>

#include "app/run_session.hpp"
#include "base/result.hpp"
#include "platform/context.hpp"

namespace fx {

// Opens the context for `plan` (plan.headless becomes true when it falls back).
Result<std::unique_ptr<Context>> openRunContext(const RunSession& session, RunPlan& plan);

}  // namespace fx
