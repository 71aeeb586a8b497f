#include "app/run_context.hpp"

#include "base/log.hpp"

namespace fx {

namespace fs = std::filesystem;

RunPlan planRun(const RunOptions& o, const std::string& exe) {
    RunPlan plan;
    plan.headless = o.forceHeadless || o.bench;  // the bench measures a fixed headless frame
    if (!plan.headless && !displayAvailable()) {
        plan.headless = true;
        log::info("no display found: rendering headless");
    }
    plan.captureDir = o.captureDir;
    plan.reportFile = o.reportFile;
    if (plan.headless && plan.captureDir.empty() && plan.reportFile.empty()) {
        // A new user's first run with no display still shows something: the picture and the report.
        plan.captureDir = fs::path("out") / exe;
        plan.reportFile = plan.captureDir / "report.json";
    }
    plan.frames = o.frames.value_or(plan.headless ? 3 : 0);
    return plan;
}

Result<std::unique_ptr<Context>> openRunContext(const RunSession& s, RunPlan& plan) {
    const RunOptions& o = s.options;
    ContextOptions co;
    // A window opens at the size the teacher left it (ui.json) unless --size says otherwise.
    Size2D remembered = !plan.headless && s.ui.windowSize ? *s.ui.windowSize : Size2D{1280, 720};
    co.size = {o.width.value_or(remembered.width), o.height.value_or(remembered.height)};
    co.title = cat("fxlab ", s.lesson->info().number, ": ", s.lesson->info().title);
    Result<std::unique_ptr<Context>> made =
        plan.headless ? createHeadlessContext(co) : createWindowContext(co);
    if (!made && !plan.headless) {
        log::warning(made.error(), "; trying headless instead");
        plan.headless = true;
        made = createHeadlessContext(co);
    }
    if (!made) return Error{made.error()};
    if (plan.headless && (co.size.width == 0 || co.size.height == 0))
        (*made)->resize({co.size.width, co.size.height});
    return made;
}

}  // namespace fx
