#include "kinds/planarparallel/planarparallelmodule.h"

#include "kinds/planarparallel/planarparallelpanel.h"

#include <QtGlobal>

namespace pkm::planarparallelkind {

// The sheet is the generic planar one. The templates are the mechanisms the П-joint document
// and the literature build from these legs (issue: "start from a template"), each a preset.
KindModule module()
{
    return {"planar-parallel",
            [](Document *document, QWidget *parent) -> KindPanel * { return new PlanarParallelPanel(document, parent); },
            nullptr,
            {
                {QT_TRANSLATE_NOOP("pkm::MainWindow", "5R (two driven cranks)"), "pp-5r"},
                {QT_TRANSLATE_NOOP("pkm::MainWindow", "5R driven by two П-joints"), "pp-5r-pjoint"},
                {QT_TRANSLATE_NOOP("pkm::MainWindow", "Constant orientation, 2 DOF, with two П-joints"), "pp-pa-pjoint"},
                {QT_TRANSLATE_NOOP("pkm::MainWindow", "3-RP̲R (three struts)"), "pp-3rpr"},
                {QT_TRANSLATE_NOOP("pkm::MainWindow", "3-R̲RR (three driven cranks)"), "pp-3rrr"},
                {QT_TRANSLATE_NOOP("pkm::MainWindow", "3-P̲RR (three driven sliders)"), "pp-3prr"},
                {QT_TRANSLATE_NOOP("pkm::MainWindow", "2-P̲RR (two driven sliders, MOMA 3a)"), "pp-2prr-moma3a"},
            }};
}

} // namespace pkm::planarparallelkind
