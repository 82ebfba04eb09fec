#include "kinds/pjoint/pjointmodule.h"

#include "kinds/pjoint/pjointplots.h"
#include "kinds/pjoint/pjointsheet.h"

namespace pkm::pjointkind {

KindModule module()
{
    return {"pjoint", [](Document *, QWidget *parent) -> KindPanel * { return new PJointPlots(parent); },
            &addSheetSections};
}

} // namespace pkm::pjointkind
