#pragma once
/// Design files (.pkm.json) and the built-in presets. A design names its mechanism kind and
/// gives parameter values and a pose in display units (mm, degrees, N …), so that a person can
/// read and edit the file.

#include "mechanism.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace pkm {

struct Design {
    QString id;          ///< preset id, or empty for a user file
    QString title;
    QString description;
    MechanismPtr mechanism;
    Pose pose;
};

struct PresetInfo {
    QString id;
    QString kind;
    QString title;
};

namespace designfile {
inline constexpr const char *formatName = "pkm-studio-design";
inline constexpr int formatVersion = 1;

/// Parses a design; `origin` names the file or preset in messages.
Result<Design> parse(const QByteArray &json, const QString &origin);
/// Loads a preset id (see presets()) or a file path.
Result<Design> load(const QString &presetOrPath);
QByteArray serialize(const Design &design);
/// Writes atomically (QSaveFile); the failure names the path.
Result<bool> save(const Design &design, const QString &path);

QList<PresetInfo> presets();

/// Sets one design parameter given in display units; the failure names the parameter.
Result<MechanismPtr> setDisplayParameter(const MechanismPtr &mechanism, const QString &name, double displayValue);
/// Solves a pose from named variable values in display units. All outputs given: inverse
/// kinematics; all inputs given: direct; a partial set keeps the others from `current`.
Result<Pose> solveDisplayVariables(const Mechanism &mechanism, const Pose &current,
                                   const QList<QPair<QString, double>> &values);
} // namespace designfile

} // namespace pkm
