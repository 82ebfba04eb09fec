// The kinds with a GUI of their own, one line each (kindmodule.h). A kind that is not here
// still has every generic panel, section and export.

#include "kinds/kindmodule.h"

#include "kinds/fourbar/fourbarmodule.h"
#include "kinds/oxglide/oxglidemodule.h"
#include "kinds/pjoint/pjointmodule.h"
#include "kinds/planarparallel/planarparallelmodule.h"

namespace pkm::kinds {

const std::vector<KindModule> &modules()
{
    static const std::vector<KindModule> all = {
        pjointkind::module(),
        oxglidekind::module(),
        fourbarkind::module(),
        planarparallelkind::module(),
    };
    return all;
}

const KindModule *find(std::string_view kind)
{
    for (const KindModule &module : modules()) {
        if (module.kind == kind)
            return &module;
    }
    return nullptr;
}

sheet::Sheet buildSheet(const Mechanism &mechanism, const Pose &pose, const sheet::Source &source)
{
    const KindModule *module = find(mechanism.kind());
    return sheet::build(mechanism, pose, source, module ? module->sheetSections : nullptr);
}

} // namespace pkm::kinds
