#pragma once
/// Design files (.pkm.json) and the built-in presets. A design names its mechanism kind and
/// gives parameter values and a pose in display units (mm, degrees, N …), so that a person can
/// read and edit the file.

#include "capabilitymap.h"
#include "mechanism.h"

#include <QByteArray>
#include <QJsonValue>
#include <QString>
#include <QStringList>

namespace pkm {

/// A pose the user keeps to come back to (a teacher's bookmarks, stepped through in class):
/// its name and every joint variable in display units, as the design file's pose.
struct Bookmark {
    QString name;
    QList<QPair<QString, double>> pose;
    bool operator==(const Bookmark &) const = default;
};

struct Design {
    QString id;          ///< preset id, or empty for a user file
    QString title;
    QString description;
    MechanismPtr mechanism;
    Pose pose;
    QList<Bookmark> bookmarks;
    /// ±tolerances of geometric design parameters (core units, core/tolerance.h), by name;
    /// saved as "tolerances": {NAME: ±value in display units}.
    ParameterSet tolerances;
    /// What the actuators must deliver (core/capabilitymap.h), core units; saved as
    /// "requirements": ["force_worst >= 50", …] in display units, as `pkm … --require` takes them.
    std::vector<capability::Requirement> requirements;
};

struct PresetInfo {
    QString id;
    QString kind;
    QString title;
    QString description; ///< in English, as the file gives it (presetText() translates it)
};

namespace designfile {
inline constexpr const char *formatName = "pkm-studio-design";
/// The version written. Version 1 saved the pose's outputs only, which lost the O-X glide's z
/// and which of a crank-rocker's two crank angles was meant; version 2 saves every joint
/// variable. Older files are read as they were written (a partial pose is solved from what it
/// gives) and saved in the current version; newer ones are refused.
inline constexpr int formatVersion = 2;
/// A saved output may differ from the one its inputs give by this much (relative, display
/// units) before the file is refused as inconsistent.
inline constexpr double savedPoseTolerance = 1e-6;
/// A design keeps at most this many bookmarks, each name at most this long (a file that says
/// more is refused: memory stays bounded whatever a file says).
inline constexpr int maxBookmarks = 100;
inline constexpr int maxBookmarkName = 200;

/// Reads a design file's "tolerances" object (display units) for `mechanism`: at most
/// tolerance::maxTolerances, each a geometric parameter with a value ≥ 0 that keeps it in its
/// domain; the failure names the parameter.
Result<ParameterSet> parseTolerances(const Mechanism &mechanism, const QJsonValue &value, const QString &origin);

/// A design file is read only up to this size (1 MiB; the presets are 1–5 kB): a larger one,
/// or a device that never ends, is refused before it is parsed.
inline constexpr qint64 maxFileBytes = qint64(1) << 20;
/// The longest title or description a design keeps, in characters (a page of text).
inline constexpr int maxTextLength = 10000;

/// The bytes of the file at `path`, read in a bounded way (at most maxFileBytes); the failure
/// names `origin` and the limit.
Result<QByteArray> readFile(const QString &path, const QString &origin);

/// A design keeps at most this many requirements (capabilitymap.h).
inline constexpr int maxRequirements = 16;

/// Reads a design file's "requirements" array of "NAME >= VALUE" strings for `mechanism`; the
/// failure names the requirement (designrequirements.cpp).
Result<std::vector<capability::Requirement>> parseRequirements(const Mechanism &mechanism, const QJsonValue &value,
                                                               const QString &origin);
/// The requirement as the file keeps it: "force_worst >= 50", the value in display units.
QString requirementText(const Mechanism &mechanism, const capability::Requirement &requirement);

/// The bookmark of `pose` called `name`: every joint variable in display units.
Bookmark bookmarkOf(const Mechanism &mechanism, const Pose &pose, const QString &name);

/// Parses a design; `origin` names the file or preset in messages.
Result<Design> parse(const QByteArray &json, const QString &origin);
/// Whether `presetOrPath` names a preset (no '/' and no ".json" ending) rather than a file.
bool isPresetId(const QString &presetOrPath);
/// Loads a preset id (see presets()) or a file path.
Result<Design> load(const QString &presetOrPath);
QByteArray serialize(const Design &design);
/// Writes atomically (QSaveFile); the failure names the path.
Result<bool> save(const Design &design, const QString &path);

QList<PresetInfo> presets();
/// A preset's title or description (as its file gives it, in English) in the current language
/// (the build hands every preset's texts to the catalogues: cmake/PresetTexts.cmake);
/// any other text (a user's own design) comes back unchanged.
QString presetText(const QString &english);

/// Sets one design parameter given in display units; the failure names the parameter.
Result<MechanismPtr> setDisplayParameter(const MechanismPtr &mechanism, const QString &name, double displayValue);
/// Solves the pose a file gives (display units) from `home`: all inputs and some outputs
/// (version 2) — the inputs decide and the outputs must agree; otherwise as
/// solveDisplayVariables().
Result<Pose> solveSavedPose(const Mechanism &mechanism, const Pose &home, const QList<QPair<QString, double>> &values);
/// Solves a pose from named variable values in display units. All outputs given: inverse
/// kinematics; all inputs given: direct; a partial set keeps the others from `current`.
Result<Pose> solveDisplayVariables(const Mechanism &mechanism, const Pose &current,
                                   const QList<QPair<QString, double>> &values);
} // namespace designfile

} // namespace pkm
