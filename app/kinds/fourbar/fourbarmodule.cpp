#include "kinds/fourbar/fourbarmodule.h"

#include "kinds/fourbar/fourbarpanel.h"
#include "kinds/fourbar/fourbarsheet.h"

namespace pkm::fourbarkind {

KindModule module()
{
    return {"fourbar",
            [](Document *document, QWidget *parent) -> KindPanel * { return new FourBarPanel(document, parent); },
            &addSheetSections};
}

} // namespace pkm::fourbarkind
