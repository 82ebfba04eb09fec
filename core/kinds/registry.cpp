#include "registry.h"

#include "fivebar/fivebar.h"
#include "fivebar/fivebarequations.h"
#include "fourbar/fourbar.h"
#include "fourbar/fourbarequations.h"
#include "moma/moma.h"
#include "moma/momaequations.h"
#include "oxglide/oxglide.h"
#include "oxglide/oxglideequations.h"
#include "pjoint/pjoint.h"
#include "pjoint/pjointequations.h"
#include "planarparallel/planarparallel.h"
#include "planarparallel/ppequations.h"
#include "text.h"

namespace pkm {

const std::vector<MechanismKind> &mechanismKinds()
{
    static const std::vector<MechanismKind> kinds = {
        {"pjoint", QT_TRANSLATE_NOOP("core", "Active П-joint"), &PJoint::createFrom, &pjoint::equations},
        {"moma", QT_TRANSLATE_NOOP("core", "MOMA 2-axis parallel mechanism"), &Moma::createFrom, &moma::equations},
        {"oxglide", QT_TRANSLATE_NOOP("core", "O-X glide hybrid mechanism"), &OxGlide::createFrom, &oxglide::equations},
        {"fourbar", QT_TRANSLATE_NOOP("core", "Planar four-bar linkage"), &FourBar::createFrom, &fourbar::equations},
        {"fivebar", QT_TRANSLATE_NOOP("core", "Planar five-bar linkage"), &FiveBar::createFrom, &fivebar::equations},
        {"planar-parallel", QT_TRANSLATE_NOOP("core", "Planar parallel mechanism (leg library)"), &PlanarParallel::createFrom, &planar::equations},
    };
    return kinds;
}

const MechanismKind *findMechanismKind(std::string_view id)
{
    for (const MechanismKind &kind : mechanismKinds()) {
        if (kind.id == id)
            return &kind;
    }
    return nullptr;
}

Result<MechanismPtr> createMechanism(std::string_view id, const ParameterSet &parameters)
{
    const MechanismKind *kind = findMechanismKind(id);
    if (!kind)
        return Failure{FailureKind::UnknownName, std::string(id),
                       text::format(text::translate("core", "Unknown mechanism kind '%1'."), {id})};
    auto defaults = kind->create({});
    if (!defaults)
        return defaults.failure();
    for (const auto &[name, value] : parameters) {
        bool known = false;
        for (const ParameterInfo &info : (*defaults)->parameterInfo())
            known = known || info.name == name;
        if (!known) {
            return Failure{FailureKind::UnknownName, name,
                           text::format(text::translate("core", "A %1 has no parameter named '%2'."),
                                        {text::label(kind->title), name})};
        }
    }
    return kind->create(parameters);
}

} // namespace pkm
