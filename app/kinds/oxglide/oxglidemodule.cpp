#include "kinds/oxglide/oxglidemodule.h"

#include "kinds/oxglide/oxglidepanel.h"

namespace pkm::oxglidekind {

// The O-X glide's sheet is the generic planar one: its exact areas come from its workspace
// (PlanarWorkspace::exactAreas).
KindModule module()
{
    return {"oxglide",
            [](Document *document, QWidget *parent) -> KindPanel * { return new OxGlidePanel(document, parent); },
            nullptr};
}

} // namespace pkm::oxglidekind
