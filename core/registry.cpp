#include "registry.h"

#include "fivebar.h"
#include "fourbar.h"
#include "moma.h"
#include "oxglide.h"
#include "pjoint.h"

namespace pkm {

const std::vector<MechanismKind> &mechanismKinds()
{
    static const std::vector<MechanismKind> kinds = {
        {"pjoint", "Active П-joint", &PJoint::createFrom},
        {"moma", "MOMA 2-axis parallel mechanism", &Moma::createFrom},
        {"oxglide", "O-X glide hybrid mechanism", &OxGlide::createFrom},
        {"fourbar", "Planar four-bar linkage", &FourBar::createFrom},
        {"fivebar", "Planar five-bar linkage", &FiveBar::createFrom},
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
        return Failure{FailureKind::UnknownName, std::string(id), "Unknown mechanism kind '" + std::string(id) + "'."};
    auto defaults = kind->create({});
    if (!defaults)
        return defaults.failure();
    for (const auto &[name, value] : parameters) {
        bool known = false;
        for (const ParameterInfo &info : (*defaults)->parameterInfo())
            known = known || info.name == name;
        if (!known) {
            return Failure{FailureKind::UnknownName, name,
                           "A " + std::string(kind->title) + " has no parameter named '" + name + "'."};
        }
    }
    return kind->create(parameters);
}

} // namespace pkm
