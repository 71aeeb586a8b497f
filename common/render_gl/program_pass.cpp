#include "render_gl/program_pass.hpp"

#include "base/log.hpp"

namespace fx {

Pass& runsWith(Pass& pass, const gl::ReloadableProgram& program) {
    if (!program.usable())
        pass.disable(cat("the ", program.sources().name(), " program did not build: ", program.error()));
    return pass;
}

void runTogether(const std::vector<Pass*>& passes) {
    for (const Pass* off : passes) {
        if (off->switchState() != PassSwitch::Disabled) continue;
        const std::string reason = off->switchReason();
        for (Pass* p : passes) p->disable(reason);
        return;
    }
}

}  // namespace fx
